#include "ao_point_list.h"

#include <darkroom/error.h>
#include <darkroom/data/formats/point_list.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace darkroom::accuracy::ao {

namespace {

bool listed(const SceneObject& o) {
    return o.representation == Representation::Points || o.representation == Representation::Lines;
}

}  // namespace

bool hasPointList(const stress::StressScene& scene) {
    for (const SceneObject& o : scene.scene->objects)
        if (listed(o)) return true;
    return false;
}

double pointListAo(const Harness& harness, const stress::StressScene& scene, const BufferPtr& gbuffer, double radius,
                   std::vector<float>& ao) {
    const SceneObject* thin = nullptr;
    for (const SceneObject& o : scene.scene->objects)
        if (listed(o)) {
            if (thin) throw Error("ao sweep: scene " + scene.name + " has more than one points or lines object");
            thin = &o;
        }
    if (!thin) throw Error("ao sweep: scene " + scene.name + " has no points or lines object");
    static std::atomic<int> serial{0};
    const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                       ("darkroom-ao-list-" + std::to_string(::getpid()) + "-" +
                                        std::to_string(serial++) + ".csv");
    {
        std::ofstream out(file);
        out << pointListCsv(*thin);
        if (!out) throw Error("ao sweep: cannot write " + file.string());
    }
    const std::map<std::string, Value> params{{"points", Value(file.string())},
                                              {"radius", Value(radius)},
                                              {"radiusUnits", Value("world")}};
    BufferPtr out;
    const double ms = harness.msPerMpix([&] { out = harness.runPass("PointListAO", gbuffer, params); },
                                        gbuffer->pixelCount());
    std::filesystem::remove(file);
    const float* a = out->requireFloat("AO");
    ao.assign(a, a + gbuffer->pixelCount());
    return ms;
}

}  // namespace darkroom::accuracy::ao
