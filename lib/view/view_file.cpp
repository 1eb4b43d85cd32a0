#include "view/view_file.h"

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cctype>
#include <fstream>
#include <iostream>

#include "util/error.h"

namespace brume {

namespace {

bool isOpenExr(std::istream& in) {
    unsigned char magic[4] = {};
    in.read(reinterpret_cast<char*>(magic), 4);
    bool exr = in.gcount() == 4 && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
    in.clear();
    in.seekg(0);
    return exr;
}

bool readOpenExrView(const std::string& path, View& view, Resolution* resolution) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        if (resolution) {
            const Imath::Box2i& window = header.dataWindow();
            resolution->width = window.max.x - window.min.x + 1;
            resolution->height = window.max.y - window.min.y + 1;
        }
        const auto* text = header.findTypedAttribute<Imf::StringAttribute>("view");
        return text && parseViewString(view, text->value()) > 0;
    } catch (const std::exception& e) {
        throw Error(path + ": " + e.what());
    }
}

// A Radiance view file or picture header: lines up to the first blank one (or the end of a view file).
bool readHeaderViews(std::istream& in, const std::string& path, View& view, Resolution* resolution) {
    bool found = false;
    std::string line;
    // Radiance's getheader gives up on a file that does not start with a printable character (binary data).
    if (!std::isprint(in.peek())) return false;
    bool ended = false;
    while (std::getline(in, line)) {
        if (line.empty() || line == "\r") {
            ended = true;
            break;
        }
        if (isViewLine(line) && parseViewString(view, line) > 0) found = true;
    }
    if (resolution) {
        if (!ended || !std::getline(in, line)) throw Error(path + ": no resolution line (not a picture)");
        *resolution = parseResolution(line, path);
    }
    return found;
}

}  // namespace

bool readViewFile(const std::string& path, View& view, Resolution* resolution) {
    if (path == "-") return readHeaderViews(std::cin, path, view, resolution);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open");
    if (isOpenExr(in)) return readOpenExrView(path, view, resolution);
    return readHeaderViews(in, path, view, resolution);
}

}  // namespace brume
