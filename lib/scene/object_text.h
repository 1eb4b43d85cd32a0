// One object as .rad text has it, read and written word for word: "modifier type identifier", then the
// counted string, integer and real arguments. The modifier stays a name: the scene reader resolves it,
// filters such as xform pass it on (their input is often a fragment whose modifiers are defined elsewhere).
#pragma once
#include <string>
#include <string_view>

#include "scene/scene.h"
#include "scene/tokenizer.h"

namespace brume {

struct ObjectText {
    std::string modifier;
    SceneObject object;  // object.modifier is unused (-1); an alias's one string is the aliased name
};

// Reads objects' words in Radiance's syntax (its isint and isflt numbers); errors name file:line.
class ObjectWords {
public:
    ObjectWords(SceneTokenizer& tokens, std::string file) : tokens_(tokens), file_(std::move(file)) {}

    // The next word; throws "unexpected end of file, expected <what>" at the end of the input.
    SceneTokenizer::Word word(std::string_view what);
    // The counted strings, integers and reals that follow an identifier.
    void readArguments(SceneObject& object);
    // A whole object (an alias "mod alias new old" included).
    ObjectText read();
    SourceLocation at(int line) const { return {file_, line}; }

private:
    size_t count(std::string_view kind);
    long integer(const SceneTokenizer::Word& w) const;
    double real(const SceneTokenizer::Word& w) const;

    SceneTokenizer& tokens_;
    std::string file_;
};

// The object as Radiance's xform writes it: "modifier type identifier" on one line, then the arguments,
// reals laid out as for the type (one point per line for polygons, cones, rings, texts, ...) as "%18.12g",
// or "%12.6g" for mist, dielectric and interface, whose arguments xform rounds to 6 digits.
std::string objectText(const ObjectText& object);

}  // namespace brume
