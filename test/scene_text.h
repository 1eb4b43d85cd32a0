// Helpers for tests that build scenes from .rad text and compute with the library.
#pragma once
#include <cmath>
#include <cstdlib>
#include <functional>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "integrator/integrator.h"
#include "render/sequence.h"
#include "scene/placed_files.h"
#include "scene/reader.h"

namespace brume::test {

inline Scene sceneFromText(const std::string& text) {
    Scene scene;
    std::istringstream in(text);
    readSceneText(scene, in, "test.rad");
    loadPlacedFiles(scene);
    return scene;
}

// Inside a closed sphere of radius 1 and reflectance ρ with a small central lamp (Φ = 4π² r² L), every wall
// point receives E = E₀/(1 − ρ) over all bounces (E₀ = Φ/(4πR²) directly).
inline std::string integratingSphere(double rho) {
    std::ostringstream s;
    s << "void plastic wall 0 0 5 " << rho << " " << rho << " " << rho << " 0 0\n"
      << "wall bubble inside 0 0 4 0 0 0 1\n"
      << "void light lamp 0 0 3 1000 1000 1000\n"
      << "lamp sphere bulb 0 0 4 0 0 0 0.02\n";
    return s.str();
}

// Point i of n on the unit sphere, spread evenly by a Fibonacci spiral.
inline glm::dvec3 fibonacciSphere(size_t i, size_t n) {
    double z = 1 - (2 * double(i) + 1) / double(n), r = std::sqrt(1 - z * z);
    double phi = double(i) * std::numbers::pi * (3 - std::sqrt(5.0));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// A scene ready to trace; holds the parsed scene so the compiled one can refer to it.
struct TestScene {
    Scene scene;
    RenderScene render;
    TestScene(const std::string& text, const MaterialSettings& m = {}) : scene(sceneFromText(text)), render(scene, m) {}
};

// The message of the Error that building a render scene from `text` throws, or "no error".
inline std::string renderSceneError(const std::string& text) {
    try {
        TestScene s(text);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// The message of the Error that `f` throws, or "no error".
inline std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// Sets RAYPATH for the life of the object, restoring it afterwards.
class ScopedRayPath {
public:
    explicit ScopedRayPath(const char* value) {
        if (const char* old = std::getenv("RAYPATH")) old_ = old;
        value ? setenv("RAYPATH", value, 1) : unsetenv("RAYPATH");
    }
    ~ScopedRayPath() { old_ ? setenv("RAYPATH", old_->c_str(), 1) : unsetenv("RAYPATH"); }

private:
    std::optional<std::string> old_;
};

// Reproducible settings (the same seed every run).
inline RenderSettings fixedSeed() {
    RenderSettings s;
    s.randomSampling = false;
    return s;
}

// One ray or sensor at a time, outside any loop over work items: with a scratch of its own and no cache
// (paths sample what records would give), at the settings' instant.
inline RayRecord trace(const Integrator& integrator, const dvec3& org, const dvec3& dir, uint64_t index,
                       double maxDistance = 0, RayTree* tree = nullptr) {
    Scratch scratch(integrator.scene());
    WorkItem item{scratch};
    return integrator.trace({org, dir, index, integrator.settings().time.value_or(0), maxDistance}, item, tree);
}
inline RayRecord irradiance(const Integrator& integrator, const dvec3& p, const dvec3& n, uint64_t index,
                            RayTree* tree = nullptr) {
    Scratch scratch(integrator.scene());
    WorkItem item{scratch};
    return integrator.irradiance({p, n, index, integrator.settings().time.value_or(0)}, item, tree);
}
inline RayRecord irradianceAtHit(const Integrator& integrator, const dvec3& org, const dvec3& dir, uint64_t index,
                                 RayTree* tree = nullptr) {
    Scratch scratch(integrator.scene());
    WorkItem item{scratch};
    return integrator.irradianceAtHit({org, dir, index, integrator.settings().time.value_or(0)}, item, tree);
}

// Mean of the first channel of `runs` independent irradiance estimates.
inline double meanIrradiance(const Integrator& integrator, const dvec3& p, const dvec3& n, int runs) {
    double sum = 0;
    for (int i = 0; i < runs; ++i) sum += irradiance(integrator, p, n, uint64_t(i)).value[0];
    return sum / runs;
}

}  // namespace brume::test
