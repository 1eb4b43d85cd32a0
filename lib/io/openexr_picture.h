// OpenEXR pictures: a Picture's pixels as the channels R, G, B and its Radiance header as OpenEXR attributes,
// so that OpenEXR readers get luminances and colours right and Brume gets its header lines back.
//
// Header line                 attribute (type)                      notes
// command lines ("rpict …")   comments (string, standard)           one line each, in order
// SOFTWARE=                   Software (string)                     OpenImageIO's name for it
// VIEW=                       view (string)                         the options as written ("-vtv -vp …");
//                                                                   several VIEW= lines, joined by spaces
// PIXASPECT= (product)        pixelAspectRatio (float, required)    1 / PIXASPECT: OpenEXR's is width/height
// CAPDATE=                    capDate (string, standard)            same "YYYY:MM:DD hh:mm:ss" local time
// GMT=                        utcOffset (float, standard)           GMT − CAPDATE in seconds
// EXPOSURE= (product)         whiteLuminance (float, standard)      179 / EXPOSURE cd/m² for RGB (1,1,1),
//                                                                   1 / EXPOSURE for XYZE (below)
// PRIMARIES=                  chromaticities (standard)             Radiance's default primaries without one
// any other line              radianceHeader (string)               one line each, in order
//
// XYZE pictures keep X, Y, Z in the channels R, G, B with the chromaticities red (1,0), green (0,1),
// blue (0,0), white (1/3,1/3): OpenEXR's convention for CIE XYZ (a channel named Y would be read as
// luminance). Radiance 6.1's XYZE has Y in cd/m² (rpict -pXYZ and ra_xyze multiply by 179), hence
// whiteLuminance 1 / EXPOSURE for them.
#pragma once
#include <string>

#include "io/picture.h"

namespace brume {

// Half keeps 11 bits of mantissa and values up to kLargestHalf (larger ones are written as kLargestHalf);
// float is exact.
enum class ExrPixels { half, float32 };
inline constexpr float kLargestHalf = 65504.f;

// Writes `picture` to `path` (ZIP compression) through a temporary file in the same directory, renamed over
// `path` once complete and on disk: a failed or interrupted write leaves whatever was at `path` before.
// Throws Error "cannot write path: reason".
void writeOpenExrPicture(const std::string& path, const Picture& picture, ExrPixels pixels);

// Reads an OpenEXR picture's R, G, B channels (or its luminance and chroma) and rebuilds the Radiance
// header lines from the attributes above: commands, SOFTWARE=, other lines, VIEW=, PIXASPECT= (when not
// 1), CAPDATE=, GMT=, EXPOSURE= (when not 1), PRIMARIES= (RGB with chromaticities), as rpict orders them.
// Throws Error naming the file.
Picture readOpenExrPicture(const std::string& path);

}  // namespace brume
