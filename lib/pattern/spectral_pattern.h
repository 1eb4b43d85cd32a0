// Radiance 6's spectral patterns (reference manual §"Spectrum" … "Specpict"): they multiply the colour of
// what they modify by a spectrum — constant (spectrum, specfile) or varying over the surface (specfunc,
// specdata, specpict). Spectra arrive as bins of equal width and enter the sampling in effect by
// spectrumFromBins, so they work with any -cs, RGB included.
#pragma once
#include <memory>

#include "pattern/pattern.h"
#include "pattern/pattern_library.h"
#include "scene/scene.h"

namespace brume {

bool isSpectralPatternType(const std::string& type);
// Throws Error (file:line) on bad arguments or data.
std::unique_ptr<Pattern> makeSpectralPattern(const SceneObject& o, PatternLibrary& lib);

}  // namespace brume
