// What the ray-input fuzz target does with one input, shared with the corpus replay test: the first byte picks
// the format (a, f or d; any other byte picks one by its value), the rest is read as rtrace's standard input
// in batches, and every ray read is traced through a small room (a lamp, a plastic floor, a glass pane) at
// -ab 1 with the irradiance cache, as rtrace traces it plainly, with -ld, -I and -i, and written as rtrace
// writes every numeric field in doubles. A bad ray (brume::Error) is fine; crashes are not, and a value
// written that is not a finite number makes this return false.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "io/ray_reader.h"
#include "io/value_writer.h"
#include "scene_text.h"

namespace brume {

inline const test::TestScene& rayRoom() {
    static const test::TestScene room(
        "void light lamp 0 0 3 100 100 100\n"
        "lamp sphere bulb 0 0 4 0 0 3 0.2\n"
        "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
        "grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n"
        "void glass clear 0 0 3 .9 .9 .9\n"
        "clear polygon pane 0 0 12 1 -1 .5 1 1 .5 1 1 2 1 -1 2\n");
    return room;
}

// -ab 1 with the irradiance cache, few samples, the same seed every run.
inline RenderSettings rayRoomSettings() {
    RenderSettings s;
    s.ambientBounces = 1;
    s.ambientDivisions = 16;
    s.ambientSupersamples = 0;
    s.ambientAccuracy = 0.2;
    s.randomSampling = false;
    return s;
}

// Whether every value rtrace would write for `rays` is finite: "-ffd -odvVwWlLcpnNrxRX" and `mode` (0,
// 'l' for -ld, 'I' or 'i').
inline bool answersAreFinite(Sequence& sequence, const std::vector<InputRay>& rays, uint64_t first, char mode) {
    std::vector<RayRecord> records(rays.size());
    const Integrator& integrator = sequence.integrator();
    sequence.run(rays.size(), 0, [&](size_t i, WorkItem& item) {
        const InputRay& in = rays[i];
        if (in.zero) return;
        RayQuery q{in.org, in.dir, first + i, 0, mode == 'l' ? in.maxDistance : 0};
        if (mode == 'I') records[i] = integrator.irradiance(q, item);
        else if (mode == 'i') records[i] = integrator.irradianceAtHit(q, item);
        else records[i] = integrator.trace(q, item);
    });
    char* data = nullptr;
    size_t size = 0;
    std::FILE* out = open_memstream(&data, &size);
    {
        ValueWriter writer(out, "odvVwWlLcpnNrxRX", 'd', rayRoom().scene);
        for (size_t i = 0; i < rays.size(); ++i) writer.write({rays[i].org, rays[i].dir, &records[i]});
    }
    std::fclose(out);
    std::vector<double> values(size / sizeof(double));
    std::memcpy(values.data(), data, values.size() * sizeof(double));
    std::free(data);
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

inline bool exerciseRays(std::string_view bytes) {
    if (bytes.empty()) return true;
    std::istringstream in{std::string(bytes.substr(1))};
    char format = std::string_view("afd").find(bytes[0]) != std::string_view::npos
                      ? bytes[0]
                      : "afd"[static_cast<unsigned char>(bytes[0]) % 3];
    RayReader reader(in, format, "(stdin)");
    RayBatches batches(reader, 64, 0);  // small batches: several cache passes in one input
    Sequence sequence(rayRoom().scene, rayRoom().render, rayRoomSettings());
    try {
        for (std::vector<InputRay> rays; batches.next(rays);)
            for (char mode : {'\0', 'l', 'I', 'i'})
                if (!answersAreFinite(sequence, rays, batches.first(), mode)) return false;
    } catch (const Error&) {
    }
    return true;
}

}  // namespace brume
