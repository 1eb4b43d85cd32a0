// The view options on a command line (-vt? -vp -vd -vu -vh -vv -vo -va -vs -vl), registered in a program's
// option table so that rpict, rtrace and vwrays parse, list and print them alike.
#pragma once
#include "util/options.h"
#include "view/view.h"

namespace brume {

void addViewOptions(OptionTable& table, View& view);

}  // namespace brume
