#include "view/view_options.h"

#include "util/error.h"
#include "view/view_file.h"

namespace brume {

namespace {

std::string vector(const dvec3& v) { return formatReal(v.x) + " " + formatReal(v.y) + " " + formatReal(v.z); }

}  // namespace

void addViewOptions(OptionTable& table, View& view) {
    table.addAttached("-vt", "view type: v (perspective), l (parallel), h a s (fisheyes), c (panorama)",
                      [&view](const std::string& letter) {
                          if (letter.size() != 1) throw Error("bad view type '-vt" + letter + "'");
                          view.type = letter[0];
                      },
                      [&view] { return std::string(1, view.type); });
    struct Entry {
        const char* name;
        int count;
        const char* help;
        std::function<std::string()> current;
    };
    auto real = [](const double& v) { return [&v] { return formatReal(v); }; };
    for (Entry e : {Entry{"-vp", 3, "view point", [&view] { return vector(view.vp); }},
                    {"-vd", 3, "view direction (its length: focal distance)", [&view] { return vector(view.vd); }},
                    {"-vu", 3, "view up", [&view] { return vector(view.vu); }},
                    {"-vh", 1, "horizontal view size", real(view.vh)}, {"-vv", 1, "vertical view size", real(view.vv)},
                    {"-vo", 1, "fore clipping distance", real(view.vo)}, {"-va", 1, "aft clipping distance", real(view.va)},
                    {"-vs", 1, "view shift", real(view.vs)}, {"-vl", 1, "view lift", real(view.vl)}}) {
        std::string name = e.name;
        table.add(name, e.count, e.help, [&view, name](const std::vector<std::string>& values) {
            std::vector<std::string> words{name};
            words.insert(words.end(), values.begin(), values.end());
            parseViewOption(view, words);
        }, e.current);
    }
    table.add("-vf", 1, "view file or picture", [&view](const std::vector<std::string>& a) {
        if (!readViewFile(a[0], view)) throw Error(a[0] + ": no view in file");
    });
}

}  // namespace brume
