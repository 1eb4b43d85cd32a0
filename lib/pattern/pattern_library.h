// What the scene's patterns share: the .cal definitions they use, compiled once into one program that
// every thread evaluates, and the data files, pictures and fonts they read, each read once.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "cal/compiler.h"
#include "cal/library.h"
#include "pattern/data_grid.h"
#include "pattern/font.h"

namespace brume {

class PatternLibrary {
public:
    PatternLibrary();
    ~PatternLibrary();

    // The context of function file `name` ("." for none), loading it on first use.
    cal::Scope load(const std::string& name, const SourceLocation& where);
    cal::ExprId expression(const std::string& text, const cal::Scope& scope, const SourceLocation& where);
    cal::FuncId function(const std::string& name, int nargs, const cal::Scope& scope, const SourceLocation& where);
    // How many arguments function `name` takes in `scope` (0 if it is not a function).
    int parameters(const std::string& name, const cal::Scope& scope) const;
    const DataGrid& dataFile(const std::string& name);
    const DataGrid& picture(const std::string& name);
    const DataGrid& hyperspectralPicture(const std::string& name);
    const Font& font(const std::string& name, const SourceLocation& where);

    // Compiles what was asked for; program() is valid from then on.
    void finish();
    const cal::Program& program() const { return program_; }

private:
    // The grid `read` makes of picture file `name` (found along RAYPATH), read once; `kind` for messages.
    const DataGrid& pictureGrid(const std::string& kind, const std::string& name,
                                const std::function<DataGrid(const std::string&)>& read);

    cal::Library library_;
    std::unique_ptr<cal::Compiler> compiler_;
    cal::Program program_;
    std::map<std::string, std::unique_ptr<DataGrid>> grids_;
    std::map<std::string, std::unique_ptr<Font>> fonts_;
};

}  // namespace brume
