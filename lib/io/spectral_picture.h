// Spectral OpenEXR pictures, in the layout of A. Fichet, R. Pacanowski and A. Wilkie, "An OpenEXR Layout
// for Spectral Images", JCGT 10(3), 2021 (jcgt.org/published/0010/03/01), as its authors' reference code
// writes and reads it (github.com/afichet/spectral-exr, lib/EXRSpectralImage.cpp):
// - one channel per band, "S0." + its centre + its unit: S0 is the first Stokes component, the radiance
//   (S1 to S3 would hold polarisation, "T." channels reflectance: neither applies to a rendering). The
//   centre is a decimal with a comma for its point, since a dot would start an OpenEXR layer, and an
//   optional exponent; the unit is an optional SI prefix and m or Hz. Brume writes nanometres with six
//   decimals, as the reference does ("S0.763,333333nm"), and reads every spelling the layout allows
//   ("S0.5,5E2nm", "S0.545,077THz").
// - only centres are stored: readers take a band to reach halfway to its neighbours, which Brume's bands
//   of equal width do.
// - string attributes spectralLayoutVersion "1.0" and emissiveUnits "W.m^-2.sr^-1", the one unit the
//   layout defines for emissive (radiance) images.
// - R, G, B beside the bands, so that viewers unaware of spectra show the picture.
// The layout's optional attributes are not written: polarisationHandedness (polarised images only), EV,
// lensTransmission, cameraResponse and per-band sensitivities (camera data that a rendering has not).
// The Radiance header goes in the attributes writeOpenExrPicture uses, so readPicture reads a spectral
// picture as it reads any OpenEXR picture: R, G, B and the header lines.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "io/openexr_picture.h"

namespace brume {

// A picture's spectral radiance: N bands per pixel, rows from the top, band centres in nm.
struct SpectralPixels {
    std::vector<double> wavelengths;  // band centres (nm), in the bands' stored order
    std::vector<float> values;        // width × height × N, pixel-major
};

// Writes `picture` (R, G, B and its header, as writeOpenExrPicture does) and one channel per band of
// `spectrum`, through a temporary file as writeOpenExrPicture does; half values beyond kLargestHalf are
// written as kLargestHalf. Throws Error "cannot write path: reason", also when `spectrum` does not fit the
// picture or two bands would have the same name.
void writeSpectralOpenExrPicture(const std::string& path, const Picture& picture, const SpectralPixels& spectrum,
                                 ExrPixels pixels);

// Reads a spectral picture's S0 bands, longest wavelength first (Radiance's order of bands, in which rpict
// renders them), and the picture as readOpenExrPicture does. The attributes are not checked, so files that
// omit them read too. Throws Error naming the file, also when it has no S0 band.
std::pair<Picture, SpectralPixels> readSpectralOpenExrPicture(const std::string& path);

}  // namespace brume
