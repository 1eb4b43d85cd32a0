// A window's Klems BSDF (LBNL/WINDOW XML) as the transmission matrix of the 3-phase method, as Radiance's
// dctimestep and rmtxop make it (cmbsdf.c's cm_loadBTDF): what WINDOW calls front transmission (light arriving
// from outdoors), each entry its BSDF times the projected solid angle of its incident patch, rows the outgoing
// patches, columns the incident ones; from the back transmission by reciprocity where the file has only that.
// Y-only files give each component the Y value; files with CIE X and Z, Radiance's RGB.
#pragma once
#include <string>

#include "matrix/matrix.h"

namespace brume {

// Whether a matrix operand names a BSDF file (".xml", any case) rather than a matrix.
bool isBsdfFile(const std::string& spec);

// Throws Error: a file that cannot be read as a Klems BSDF, one without transmission.
Matrix transmissionMatrix(const std::string& path);

}  // namespace brume
