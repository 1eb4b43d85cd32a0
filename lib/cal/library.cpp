#include "cal/library.h"

#include <algorithm>

#include "cal/builtins.h"
#include "cal/embedded.h"
#include "cal/lexer.h"
#include "cal/parser.h"
#include "scene/raypath.h"

namespace brume::cal {

namespace {

constexpr char kMark = '`';

// Radiance's qualname at level 0: the key a definition of `name` made in `context` is stored under.
std::string qualified(std::string_view name, std::string_view context) {
    if (name.starts_with(kMark)) name.remove_prefix(1);                              // explicitly local
    if (name.ends_with(kMark)) return std::string(name.substr(0, name.size() - 1));  // explicitly global
    return std::string(name) + std::string(context);
}

bool explicitContext(std::string_view name) { return name.starts_with(kMark) || name.ends_with(kMark); }

bool sameDefinition(const Definition& a, const Definition& b) {
    return a.params == b.params && a.constant == b.constant && sameExpr(a.body, b.body);
}

}  // namespace

// Radiance's calcontext: the name without a ".cal" suffix, characters that cannot be in a name replaced
// by '_', after a context mark.
Scope scopeOfFile(std::string_view name) {
    if (name == ".") return {};
    if (name.size() > 4) {
        std::string suffix(name.substr(name.size() - 4));
        std::transform(suffix.begin(), suffix.end(), suffix.begin(), [](unsigned char c) { return std::tolower(c); });
        if (suffix == ".cal") name.remove_suffix(4);
    }
    while (name.starts_with(kMark)) name.remove_prefix(1);
    std::string context(1, kMark);
    for (char c : name) context += isNameChar(c) ? c : '_';
    while (context.ends_with(kMark)) context.pop_back();
    return {context};
}

Library::Library() { loadText(findEmbedded(embeddedCalFiles(), "rayinit.cal")->text, "rayinit.cal"); }

Scope Library::loadFile(const std::string& name, const SourceLocation& where) {
    Scope scope = scopeOfFile(name);
    if (scope.context.empty() || loaded_.count(scope.context)) return scope;
    FileText file = readLibraryFile(name, embeddedCalFiles(), "function file", where);
    loadText(file.text, file.origin, scope);
    loaded_.insert(scope.context);
    return scope;
}

void Library::loadText(std::string_view text, const std::string& origin, const Scope& scope) {
    // Parsed whole before anything is defined: a file with a syntax error defines nothing.
    for (Definition& d : parseDefinitions(text, origin)) {
        d.context = scope.context;
        define(std::move(d));
    }
}

void Library::redefine(std::string_view text, const std::string& origin) {
    for (Definition& d : parseDefinitions(text, origin)) define(std::move(d), true);
}

void Library::define(Definition d, bool quietly) {
    std::string key = qualified(d.name, d.context);
    auto& slot = definitions_[key];
    if (!quietly && slot && !sameDefinition(*slot, d))
        warn(d.where.str() + ": " + key + (slot->constant ? ": constant redefined" : ": redefined"));
    else if (!quietly && !slot && d.isFunction() && findBuiltin(d.name))
        warn(d.where.str() + ": " + key + ": definition hides library function");
    if (slot) replaced_.push_back(std::move(slot));
    slot = std::make_unique<const Definition>(std::move(d));
}

const Definition* Library::find(std::string_view name, const Scope& scope) const {
    auto it = definitions_.find(qualified(name, scope.context));
    if (it == definitions_.end() && !explicitContext(name) && !scope.context.empty())
        it = definitions_.find(std::string(name));
    return it == definitions_.end() ? nullptr : it->second.get();
}

}  // namespace brume::cal
