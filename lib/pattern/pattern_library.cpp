#include "pattern/pattern_library.h"

#include "scene/raypath.h"
#include "util/error.h"

namespace brume {

PatternLibrary::PatternLibrary() : compiler_(std::make_unique<cal::Compiler>(library_)) {}

PatternLibrary::~PatternLibrary() = default;

cal::Scope PatternLibrary::load(const std::string& name, const SourceLocation& where) {
    return library_.loadFile(name, where);
}

cal::ExprId PatternLibrary::expression(const std::string& text, const cal::Scope& scope, const SourceLocation& where) {
    return compiler_->expression(text, scope, where);
}

cal::FuncId PatternLibrary::function(const std::string& name, int nargs, const cal::Scope& scope,
                                     const SourceLocation& where) {
    return compiler_->function(name, nargs, scope, where);
}

int PatternLibrary::parameters(const std::string& name, const cal::Scope& scope) const {
    const cal::Definition* d = library_.find(name, scope);
    return d ? int(d->params.size()) : 0;
}

const DataGrid& PatternLibrary::dataFile(const std::string& name) {
    auto& grid = grids_["data:" + name];
    if (!grid) grid = std::make_unique<DataGrid>(DataGrid::readDataFile(name));
    return *grid;
}

const DataGrid& PatternLibrary::picture(const std::string& name) {
    return pictureGrid("picture", name, [](const std::string& path) { return DataGrid::fromPicture(readPicture(path)); });
}

const DataGrid& PatternLibrary::hyperspectralPicture(const std::string& name) {
    return pictureGrid("hyperspectral picture", name, [](const std::string& path) {
        return DataGrid::fromHyperspectralPicture(readHyperspectralPicture(path));
    });
}

const DataGrid& PatternLibrary::pictureGrid(const std::string& kind, const std::string& name,
                                            const std::function<DataGrid(const std::string&)>& read) {
    auto& grid = grids_[kind + ":" + name];
    if (!grid) {
        std::string path = findOnRayPath(name);
        if (path.empty()) throw Error("cannot find " + kind + " file \"" + name + "\"");
        grid = std::make_unique<DataGrid>(read(path));
    }
    return *grid;
}

const Font& PatternLibrary::font(const std::string& name, const SourceLocation& where) {
    auto& font = fonts_[name];
    if (!font) font = std::make_unique<Font>(loadFont(name, where));
    return *font;
}

void PatternLibrary::finish() { program_ = std::move(*compiler_).finish(); }

}  // namespace brume
