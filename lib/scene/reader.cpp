#include "scene/reader.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "scene/command.h"
#include "scene/object_text.h"
#include "scene/raypath.h"
#include "scene/tokenizer.h"

namespace brume {

namespace {

using Word = SceneTokenizer::Word;

// Radiance's keywords for "no modifier" and, in aliases only, "the target's modifier".
constexpr const char* kVoid = "void";
constexpr const char* kInherit = "inherit";

class SceneParser {
public:
    SceneParser(Scene& scene, std::streambuf* in, std::string name, const ReadOptions& options)
        : scene_(scene), tokens_(in, name), words_(tokens_, name), name_(std::move(name)), options_(options) {}

    void parse() {
        size_t before = scene_.objects.size();
        for (int c; (c = tokens_.peek()) != std::char_traits<char>::eof();) {
            if (c == '#')
                tokens_.restOfLine(false);
            else if (c == '!')
                parseCommand();
            else
                parseObject();
        }
        if (scene_.objects.size() == before) warn(name_ + ": empty scene file");
    }

private:
    SourceLocation at(int line) const { return {name_, line}; }

    // The output of a "!command" line is scene text, named after the line for messages
    // ("scene.rad:4: !xform box.rad:12: ...").
    void parseCommand() {
        SourceLocation where = at(tokens_.line());
        std::string command = tokens_.restOfLine(true).substr(1);
        if (!options_.allowCommands) throw Error(where, "commands are not allowed here: !" + command);
        std::string output;
        try {
            output = commandOutput(command);
        } catch (const Error& e) {
            throw Error(where, e.what());
        }
        std::istringstream text(output);
        SceneParser(scene_, text.rdbuf(), where.str() + ": !" + command, options_).parse();
    }

    void parseObject() {
        Word modifier = words_.word("modifier");
        int line = modifier.line;
        bool inherit = modifier.text == kInherit;
        int modifierIndex = inherit ? -1 : resolveModifier(modifier);
        SceneObject object;
        object.type = words_.word("object type").text;
        object.name = words_.word("identifier").text;
        object.where = at(line);
        checkIdentifier(object);
        if (object.type == "alias") {
            addAlias(std::move(object), modifierIndex, inherit);
            return;
        }
        if (inherit) throw Error(at(line), std::string("'") + kInherit + "' modifier outside an alias");
        object.modifier = modifierIndex;
        words_.readArguments(object);
        scene_.add(std::move(object));
    }

    int resolveModifier(const Word& modifier) {
        if (modifier.text == kVoid) return -1;
        if (modifier.text.find('\t') != std::string::npos)
            throw Error(at(modifier.line), "tab in modifier name '" + modifier.text + "'");
        int index = scene_.findModifier(modifier.text);
        if (index < 0) throw Error(at(modifier.line), "undefined modifier '" + modifier.text + "'");
        return index;
    }

    // Radiance's restrictions: names are tab-free (tools print them tab-separated) and a modifier
    // may not take a keyword's name.
    void checkIdentifier(const SceneObject& object) const {
        if (object.name.find('\t') != std::string::npos)
            throw Error(object.where, "tab in identifier '" + object.name + "'");
        if (isModifierType(object.type) && (object.name == kVoid || object.name == kInherit))
            throw Error(object.where, "illegal modifier name '" + object.name + "'");
    }

    // "mod alias new old": `new` is a copy of the modifier `old`, with modifier `mod` unless that is
    // "inherit" (keep old's). Radiance resolves `old` when the alias is read, as done here.
    void addAlias(SceneObject alias, int modifierIndex, bool inherit) {
        Word reference = words_.word("alias reference");
        int target = scene_.findModifier(reference.text);
        if (target < 0) throw Error(at(reference.line), "alias of undefined modifier '" + reference.text + "'");
        SceneObject copy = scene_.objects[target];
        copy.name = std::move(alias.name);
        copy.where = std::move(alias.where);
        if (!inherit) copy.modifier = modifierIndex;
        scene_.add(std::move(copy));
    }

    Scene& scene_;
    SceneTokenizer tokens_;
    ObjectWords words_;
    std::string name_;
    const ReadOptions& options_;
};

// A file name as rtrace or oconv would open it: along RAYPATH, or as given.
std::string locate(const std::string& path, const ReadOptions& options) {
    std::string found = options.searchRayPath ? findOnRayPath(path) : path;
    if (found.empty() || access(found.c_str(), R_OK) != 0) {
        std::error_code ec;
        if (std::filesystem::exists(path, ec)) throw Error(SourceLocation{path}, "cannot read scene file");
        throw Error(SourceLocation{path}, options.searchRayPath ? "cannot find scene file along RAYPATH"
                                                                : "cannot find scene file");
    }
    std::error_code ec;
    if (std::filesystem::is_directory(found, ec)) throw Error(SourceLocation{found}, "is a directory");
    return found;
}

void readCommandOutput(Scene& scene, const std::string& command, const ReadOptions& options) {
    if (!options.allowCommands) throw Error(command + ": commands are not allowed here");
    std::istringstream text(commandOutput(command.substr(1)));
    readSceneText(scene, text, command, options);
}

}  // namespace

void readSceneText(Scene& scene, std::istream& in, const std::string& name, const ReadOptions& options) {
    SceneParser(scene, in.rdbuf(), name, options).parse();
}

void readSceneFile(Scene& scene, const std::string& path, const ReadOptions& options) {
    scene.sources.push_back(path);
    if (path == "-") return readSceneText(scene, std::cin, "standard input", options);
    if (path.starts_with('!')) return readCommandOutput(scene, path, options);
    std::string found = locate(path, options);
    scene.sources.back() = found;
    std::ifstream in(found, std::ios::binary);
    if (!in) throw Error(SourceLocation{found}, "cannot open scene file");
    readSceneText(scene, in, found, options);
}

}  // namespace brume
