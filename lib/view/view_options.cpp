#include "view/view_options.h"

#include "util/error.h"
#include "view/view_file.h"

namespace brume {

void addViewOptions(OptionTable& table, View& view) {
    table.addAttached("-vt", "view type: v (perspective), l (parallel), h a s (fisheyes), c (panorama)",
                      [&view](const std::string& letter) {
                          if (letter.size() != 1) throw Error("bad view type '-vt" + letter + "'");
                          view.type = letter[0];
                      });
    struct Entry {
        const char* name;
        int count;
        const char* help;
    };
    for (Entry e : {Entry{"-vp", 3, "view point"}, {"-vd", 3, "view direction (its length: focal distance)"},
                    {"-vu", 3, "view up"}, {"-vh", 1, "horizontal view size"}, {"-vv", 1, "vertical view size"},
                    {"-vo", 1, "fore clipping distance"}, {"-va", 1, "aft clipping distance"},
                    {"-vs", 1, "view shift"}, {"-vl", 1, "view lift"}}) {
        std::string name = e.name;
        table.add(name, e.count, e.help, [&view, name](const std::vector<std::string>& values) {
            std::vector<std::string> words{name};
            words.insert(words.end(), values.begin(), values.end());
            parseViewOption(view, words);
        });
    }
    table.add("-vf", 1, "view file or picture", [&view](const std::vector<std::string>& a) {
        if (!readViewFile(a[0], view)) throw Error(a[0] + ": no view in file");
    });
}

}  // namespace brume
