// The definitions of the .cal language: Brume's rayinit.cal, then the files patterns name.
//
// Names live in contexts, as in Radiance (rt/func.c, common/caldefn.c): rayinit.cal and text loaded
// without a scope define global names; a file a pattern names (say "skybright.cal") is loaded once, into
// its own context, so two files may each define `U` without clashing. A name used in a context means
// its definition there if there is one, otherwise the global one. A name ending in '`' is global, one
// starting with '`' is local only. A later definition of a name in the same context replaces the earlier
// one (with a warning if it differs); references resolve when compiled, not when defined.
#pragma once
#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "cal/expression.h"

namespace brume::cal {

// A context: "" is the global one; a file's is '`' and its name without ".cal".
struct Scope {
    std::string context;
};

// The context of the file a pattern names; "." (no file) is the global context.
Scope scopeOfFile(std::string_view name);

class Library {
public:
    // With Brume's rayinit.cal (always the embedded one: it defines the channels the renderer fills).
    Library();

    // Loads a .cal file into its own context, once: from RAYPATH, else from Brume's standard library.
    // "." loads nothing and gives the global scope. `where` names the reference in messages.
    Scope loadFile(const std::string& name, const SourceLocation& where = {});
    // Definitions from text; `origin` names it in messages.
    void loadText(std::string_view text, const std::string& origin, const Scope& scope = {});
    // The same, replacing earlier definitions without a warning: a command line's parameters, and files that
    // knowingly redefine what Brume's rayinit.cal defines (rcontrib's -p and -f; Radiance's reinhartb.cal
    // defines its own mod, Asin and Atan2).
    void redefine(std::string_view text, const std::string& origin);

    // The definition `name` means in `scope`, or nullptr.
    const Definition* find(std::string_view name, const Scope& scope) const;
    // Changes whenever a definition is added or replaced.
    uint64_t version() const { return replaced_.size() + definitions_.size(); }

private:
    void define(Definition d, bool quietly = false);

    std::unordered_map<std::string, std::unique_ptr<const Definition>> definitions_;
    // Kept for Compilers that have already compiled them.
    std::vector<std::unique_ptr<const Definition>> replaced_;
    std::set<std::string> loaded_;  // contexts of loaded files
};

}  // namespace brume::cal
