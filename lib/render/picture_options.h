// The picture options of rpict (-x -y -pa -pj -pd -ps -pt -pm), declared once for the programs that render
// pictures (rpict, mkcache).
#pragma once
#include "render/picture_renderer.h"
#include "util/options.h"

namespace brume {

// Adds the picture options to `table`, each setting `settings` (which must outlive the table).
void addPictureOptions(OptionTable& table, PictureSettings& settings);

// Fits `settings` to `view` (fitResolution) and refuses a picture with no pixels or too many.
void fitPictureResolution(const View& view, PictureSettings& settings);

}  // namespace brume
