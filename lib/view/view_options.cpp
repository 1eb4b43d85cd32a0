#include "view/view_options.h"

#include <cstdio>

#include "util/error.h"

namespace brume {

namespace {

const auto& number = formatReal;

std::string vector(const dvec3& v) { return number(v.x) + " " + number(v.y) + " " + number(v.z); }

// An option with `count` numbers, read by parseViewOption from the option and its words.
void addNumbers(OptionTable& t, View& view, const std::string& name, int count, const std::string& help,
                std::function<std::string()> current) {
    t.add(name, count, help, [&view, name](const std::vector<std::string>& a) {
        std::vector<std::string> words{name};
        words.insert(words.end(), a.begin(), a.end());
        parseViewOption(view, words);
    }, std::move(current));
}

}  // namespace

void addViewOptions(OptionTable& t, View& view) {
    t.addAttached("-vt", "view type: v (perspective) l (parallel) h a s (fisheyes) c (cylindrical)",
                  [&view](const std::string& v) {
                      if (v.size() != 1) throw Error("bad view type '-vt" + v + "'");
                      view.type = v[0];
                  },
                  [&view] { return std::string(1, view.type); });
    addNumbers(t, view, "-vp", 3, "view point", [&view] { return vector(view.vp); });
    addNumbers(t, view, "-vd", 3, "view direction (its length: the focal distance for -pd)",
               [&view] { return vector(view.vd); });
    addNumbers(t, view, "-vu", 3, "view up", [&view] { return vector(view.vu); });
    addNumbers(t, view, "-vh", 1, "view horizontal size", [&view] { return number(view.vh); });
    addNumbers(t, view, "-vv", 1, "view vertical size", [&view] { return number(view.vv); });
    addNumbers(t, view, "-vo", 1, "view fore clipping plane", [&view] { return number(view.vo); });
    addNumbers(t, view, "-va", 1, "view aft clipping plane", [&view] { return number(view.va); });
    addNumbers(t, view, "-vs", 1, "view shift", [&view] { return number(view.vs); });
    addNumbers(t, view, "-vl", 1, "view lift", [&view] { return number(view.vl); });
}

}  // namespace brume
