// The rendering options rtrace and rpict share (-a*, -d*, -l*, -s*, -bv, -u, -i), declared once.
#pragma once
#include "integrator/settings.h"
#include "util/options.h"

namespace brume {

// Registers the options that set `settings`; `irradianceAtHit` receives -i.
void addRenderOptions(OptionTable& table, RenderSettings& settings, bool& irradianceAtHit);

}  // namespace brume
