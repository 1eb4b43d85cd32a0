// Views from files, for -vf: view files (lines such as "rvu -vtv -vp 1 2 3 ..." or "VIEW= -vh 60"), the
// information headers of Radiance pictures (their VIEW= lines) and OpenEXR pictures written by Brume
// (a string attribute "view" holding the view options). Radiance's viewfile.
#pragma once
#include <string>

#include "io/resolution.h"
#include "view/view.h"

namespace brume {

// Applies every view line of the file at `path` ("-" for the standard input) to `view`, in order, so that
// later lines override earlier ones and options they do not name keep their values; lines count as view
// lines as isViewLine decides, and a Radiance file is read up to the blank line that ends its header.
// Returns whether any view was found. With `resolution`, the file must be a picture: its resolution line
// (or an OpenEXR picture's data window) is returned there. Throws Error "path: cannot open" and, for a
// picture without a resolution line, "path: ...".
bool readViewFile(const std::string& path, View& view, Resolution* resolution = nullptr);

}  // namespace brume
