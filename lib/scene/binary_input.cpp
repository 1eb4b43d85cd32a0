#include "scene/binary_input.h"

#include <charconv>
#include <cmath>

namespace brume {

void BinaryInput::fail(const std::string& what) const { throw Error(SourceLocation{name_}, what); }

int BinaryInput::byte() {
    int c = in_->sbumpc();
    if (c == std::char_traits<char>::eof()) fail("truncated " + kind_);
    return c;
}

long BinaryInput::integer(int size) {
    long value = static_cast<signed char>(byte());
    for (int i = 1; i < size; ++i) value = static_cast<long>(static_cast<unsigned long>(value) << 8) | byte();
    return value;
}

double BinaryInput::real() {
    long mantissa = integer(4);
    int exponent = static_cast<signed char>(byte());
    if (mantissa == 0) return 0;
    return std::ldexp((mantissa + 0.5 - (mantissa < 0)) / 2147483647.0, exponent);
}

std::string BinaryInput::string() {
    std::string s;
    for (int c; (c = byte()) != 0;) s += static_cast<char>(c);
    return s;
}

size_t BinaryInput::count(int size) {
    long n = integer(size);
    if (n < 0) fail("damaged " + kind_ + " (negative count)");
    return static_cast<size_t>(n);
}

double BinaryInput::textNumber(const std::string& what) {
    std::string s = string();
    double value = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) fail("bad " + kind_ + " " + what);
    return value;
}

std::optional<std::vector<std::string>> readInfoHeader(std::istream& in, size_t limit) {
    std::vector<std::string> lines;
    size_t bytes = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.ends_with('\r')) line.pop_back();
        if (line.empty()) return lines;
        bytes += line.size() + 1;
        if (bytes > limit) return std::nullopt;
        lines.push_back(std::move(line));
    }
    return std::nullopt;
}

std::optional<std::string> formatOf(const std::string& line) {
    if (!line.starts_with("FORMAT=")) return std::nullopt;
    size_t begin = line.find_first_not_of(" \t", 7), end = line.find_last_not_of(" \t");
    return begin == std::string::npos ? std::string() : line.substr(begin, end + 1 - begin);
}

void skipOctreeNodes(BinaryInput& input, int objectSize) {
    for (size_t pending = 1; pending > 0; --pending) {
        switch (input.byte()) {
            case 0:
                break;
            case 1:
                for (size_t n = input.count(objectSize); n > 0; --n) input.integer(objectSize);
                break;
            case 2:
                pending += 8;
                break;
            default:
                input.fail("damaged " + input.kind());
        }
    }
}

namespace {

// One frozen alias, resolved into a copy of its target.
SceneObject resolveAlias(const Scene& scene, const SceneObject& alias, BinaryInput& input) {
    int target = alias.modifier;
    if (alias.strings.size() == 1) target = scene.findModifier(alias.strings[0]);
    if (alias.strings.size() > 1 || target < 0) input.fail("bad alias '" + alias.name + "'");
    SceneObject copy = scene.objects[target];
    copy.name = alias.name;
    copy.where = alias.where;
    if (!alias.strings.empty()) copy.modifier = alias.modifier;
    return copy;
}

// Reads one frozen object into `object`; false at the end of the list.
bool readObject(BinaryInput& input, int objectSize, const std::vector<std::string>& types, int first,
                const Scene& scene, SceneObject& object) {
    int type = static_cast<signed char>(input.byte());
    if (type == -1) return false;
    if (type < 0 || static_cast<size_t>(type) >= types.size()) input.fail("reference to unknown type");
    object.type = types[type];
    long modifier = input.integer(objectSize);
    if (modifier != -1 && (modifier < 0 || modifier >= static_cast<long>(scene.objects.size()) - first))
        input.fail("bad modifier reference");  // modifiers always precede their users
    object.modifier = modifier == -1 ? -1 : static_cast<int>(first + modifier);
    object.name = input.string();
    for (size_t n = input.count(2); n > 0; --n) object.strings.push_back(input.string());
    for (size_t n = input.count(2); n > 0; --n) object.reals.push_back(input.real());
    object.where = SourceLocation{input.name()};
    return true;
}

}  // namespace

size_t readFrozenObjects(Scene& scene, BinaryInput& input, int objectSize) {
    std::vector<std::string> types;
    for (std::string type; !(type = input.string()).empty();) types.push_back(std::move(type));
    int first = static_cast<int>(scene.objects.size());
    for (SceneObject object; readObject(input, objectSize, types, first, scene, object); object = {})
        scene.add(object.type == "alias" ? resolveAlias(scene, object, input) : std::move(object));
    return scene.objects.size() - first;
}

}  // namespace brume
