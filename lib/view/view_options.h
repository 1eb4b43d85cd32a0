// The view options of rpict, rvu and vwrays as entries of a program's option table: -vt? -vp -vd -vu -vh
// -vv -vo -va -vs -vl, and -vf file, all applied to one View in command-line order.
#pragma once
#include "util/options.h"
#include "view/view.h"

namespace brume {

// Adds the view options to `table`, each applied to `view` (which must outlive the table). -vf reads a view
// file or picture (readViewFile) and throws Error "file: no view in file" when it holds none.
void addViewOptions(OptionTable& table, View& view);

}  // namespace brume
