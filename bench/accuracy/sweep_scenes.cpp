// Sweep "scenes": a thumbnail of every stress scene at every knob value (the
// harness's colour mapping of a 1-sample capture), and its coverage, so the
// docs can show what each chart was measured on.
#include "harness.h"

#include <darkroom/accuracy/stress_scenes.h>

#include <cmath>
#include <iostream>

namespace darkroom::accuracy {
namespace {

void sweepScenes(Harness& harness, Csv& csv) {
    stress::Options so;
    so.width = so.height = harness.options().size;
    for (const std::string& family : stress::families()) {
        for (const stress::StressScene& scene : stress::sweep(family, so)) {
            auto backend = harness.backend(scene);
            CaptureRequest request;
            request.scalars = {scene.colorField};
            BufferPtr gbuffer;
            const double ms = harness.msPerMpix(
                [&] { gbuffer = backend->render(scene.camera, request, harness.context()); },
                gbuffer ? gbuffer->pixelCount() : std::size_t(scene.camera.width) * scene.camera.height);
            const float* z = gbuffer->requireFloat("Z");
            std::size_t covered = 0;
            for (std::size_t i = 0; i < gbuffer->pixelCount(); ++i) covered += std::isfinite(z[i]);
            Row row;
            row.sweep = "scenes";
            row.scene = scene.name;
            row.family = scene.family;
            row.knob = scene.knob;
            row.knobValue = scene.knobValue;
            row.method = "capture 1 spp";
            row.msPerMpix = ms;
            row.metric = "coverage";
            row.value = double(covered) / double(gbuffer->pixelCount());
            csv.add(row);
            row.metric = "triangles+primitives";
            double primitives = 0;
            for (const SceneObject& o : scene.scene->objects)
                primitives += o.representation == Representation::Surface ? double(o.indices.size() / 3)
                              : o.representation == Representation::Lines ? double(o.indices.size())
                                                                           : double(o.vertexCount());
            row.value = primitives;
            csv.add(row);
            harness.writePicture(*harness.colorize(scene, gbuffer), {"R", "G", "B"}, "scene-" + scene.name);
            std::cerr << "scenes " << scene.name << ": " << primitives << " primitives\n";
        }
    }
}

}  // namespace

DARKROOM_ACCURACY_SWEEP("scenes", "a thumbnail and the coverage of every stress scene", sweepScenes);

}  // namespace darkroom::accuracy
