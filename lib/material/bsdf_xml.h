// Reading LBNL/WINDOW BSDF files (the XML schema of WINDOW 6 and genBSDF: WindowElement, Optical, Layer,
// DataDefinition, WavelengthData blocks of Klems matrices). Only what Radiance reads: the first layer,
// "Visible" (CIE Y) data, with "CIE-X" and "CIE-Z" giving colour when present; other wavelengths
// ("Solar", …) are skipped.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "material/klems_basis.h"

namespace brume {

// One scattering distribution as a matrix of BSDF values (1/sr) over (outgoing, incident) patches.
struct KlemsMatrix {
    const KlemsBasis* in = nullptr;   // the columns' basis
    const KlemsBasis* out = nullptr;  // the rows'
    KlemsSide inSide, outSide;
    std::vector<float> y;    // CIE Y, [o * in->size() + i]
    std::vector<float> rgb;  // 3 per entry, Radiance RGB; empty for Y-only data

    float value(int o, int i) const { return y[size_t(o) * size_t(in->size()) + size_t(i)]; }
};

// The four distributions in Radiance's orientation: "front" is the side the surface normal points to,
// which WINDOW calls the back (WINDOW's front faces outdoors, a window's normal indoors).
struct KlemsData {
    std::optional<KlemsMatrix> reflectFront, reflectBack;  // light arriving on, and leaving, that side
    std::optional<KlemsMatrix> transmitFront, transmitBack;  // light arriving on that side
    std::vector<std::unique_ptr<KlemsBasis>> ownBases;  // bases the file defines beyond the standard ones
};

// Reads file `path`, shown as `shownAs` in messages. Throws Error "file:line: …" on malformed or
// unsupported files (tensor trees among them).
KlemsData readKlemsXml(const std::string& path, const std::string& shownAs);

}  // namespace brume
