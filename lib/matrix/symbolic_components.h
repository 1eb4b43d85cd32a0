// Radiance's symbolic components of a matrix (rmtxop -c R, Y, M and so on): the weights that turn its
// components (RGB, or spectral bands) into red, green, blue, CIE X, Y, Z, scotopic or melanopic values.
#pragma once
#include <string>
#include <vector>

#include "matrix/matrix.h"
#include "spectrum/spectral_sampling.h"

namespace brume {

// The bands of a matrix of more than 3 components: of equal width over WAVELENGTH_SPLITS' range (its first
// and last wavelengths), else over Radiance's 380-780 nm; the longest first. Throws Error for a range Brume does
// not sample (validSpectralRange).
SpectralSampling bandsOf(const Matrix& m);

// The weights (m.comps per letter, letter after letter) of R, G, B; X, Y, Z (CIE, Y the luminance), S
// (scotopic), M (melanopic) times 179 lm/W (S: 412), lower case without it; A, the mean. Of an RGB matrix,
// Radiance 6.1's rmtxop's weights for its primaries; of a spectral one, each band's share of each curve (R,
// G and B: of X, Y and Z, turned into Radiance's RGB). Throws Error for fewer than 3 components or another
// letter.
std::vector<double> symbolWeights(const std::string& symbols, const Matrix& m);

}  // namespace brume
