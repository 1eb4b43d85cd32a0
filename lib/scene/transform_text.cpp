#include "scene/transform_text.h"

#include <sstream>

#include "scene/command.h"

namespace brume {

namespace {

void transformCommand(SceneTokenizer& tokens, const std::string& name, const SceneTransform& how, std::ostream& out) {
    SourceLocation where{name, tokens.line()};
    std::string line = tokens.restOfLine(true);
    if (!how.expandCommands) {
        out << '\n' << line << how.commandPipe << '\n';
        return;
    }
    std::string output;
    try {
        output = commandOutput(line.substr(1));
    } catch (const Error& e) {
        throw Error(where, e.what());
    }
    std::istringstream text(output);
    transformSceneText(text, where.str() + ": " + line, how, out);
}

}  // namespace

void transformSceneText(std::istream& in, const std::string& name, const SceneTransform& how, std::ostream& out) {
    SceneTokenizer tokens(in.rdbuf(), name);
    ObjectWords words(tokens, name);
    bool empty = true;
    for (int c; (c = tokens.peek()) != std::char_traits<char>::eof();) {
        if (c == '#') {
            out << tokens.restOfLine(false) << '\n';
            continue;
        }
        empty = false;
        if (c == '!') {
            transformCommand(tokens, name, how, out);
            continue;
        }
        ObjectText object = words.read();
        transformObject(object, how.objects);
        out << '\n' << objectText(object);
    }
    if (empty) warn(name + ": empty scene file");
}

}  // namespace brume
