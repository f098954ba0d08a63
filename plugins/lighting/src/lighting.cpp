#include "lighting.h"

#include <darkroom/error.h>
#include <darkroom/view_geometry.h>
#include <darkroom/channel_text.h>

#include <algorithm>
#include <cmath>

namespace darkroom {

namespace {

struct Light {
    V3f toLight;  // unit, SDK view space (z forward)
    float intensity = 0;
};

V3f unit(const V3f& v, const std::string& what) {
    const float l = length(v);
    if (!(l > 0) || !std::isfinite(l)) throw Error(what + " is not a direction (zero, NaN or infinite)");
    return v * (1.0f / l);
}

}  // namespace

void Lighting::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const int w = in->width(), h = in->height();
    const std::size_t n = in->pixelCount();
    const float* z = requireDepth(*in);
    const Camera camera = camera_.get(ctx, *in, z);
    const ViewGeometry vg(camera, w, h);
    const float* albedo[3] = {in->requireFloat("R"), in->requireFloat("G"), in->requireFloat("B")};

    // Normals in SDK view space, facing the camera (two-sided lighting).
    const Normals which = ctx.get(normals_);
    const BufferPtr geometry = ctx.get(geometry_);
    if (geometry && (geometry->width() != w || geometry->height() != h))
        throw Error("input 'geometry' is " + std::to_string(geometry->width()) + " x " +
                    std::to_string(geometry->height()) + " but 'image' is " + std::to_string(w) + " x " +
                    std::to_string(h));
    const Buffer& source = geometry ? *geometry : *in;
    const float* world[3] = {source.hostFloat("N.x"), source.hostFloat("N.y"), source.hostFloat("N.z")};
    const bool haveCaptured = world[0] && world[1] && world[2];
    if (which == Normals::Captured && !haveCaptured)
        throw Error(std::string("normals: captured needs N.x, N.y and N.z in input '") +
                    (geometry ? "geometry" : "image") + "'; it has " + channelListText(source));
    std::vector<float> nv[3] = {std::vector<float>(n), std::vector<float>(n), std::vector<float>(n)};
    float* view[3] = {nv[0].data(), nv[1].data(), nv[2].data()};
    if (haveCaptured && which != Normals::Reconstructed) {
        worldToViewNormals(ctx, world, n, camera, view);
    } else {
        NormalOutputs o;
        std::copy(view, view + 3, o.view);
        reconstructNormals(ctx, z, w, h, camera, NormalMethod::Extrapolated, o);
    }

    // Lights, towards the light, in SDK view space.
    std::vector<Light> lights;
    const bool worldSpace = ctx.get(space_) == Space::World;
    auto toView = [&](const Vec3& d) {
        return worldSpace ? vg.toView(d) : V3f{float(d.x), float(d.y), float(-d.z)};
    };
    if (ctx.get(mode_) == Mode::Headlight) {
        lights.push_back({V3f{0, 0, -1}, float(ctx.get(intensity1_))});
    } else {
        const Vec3In* dirs[4] = {&direction1_, &direction2_, &direction3_, &direction4_};
        const FloatIn* amounts[4] = {&intensity1_, &intensity2_, &intensity3_, &intensity4_};
        for (int k = 0; k < int(ctx.get(lightCount_)); ++k)
            lights.push_back({unit(toView(ctx.get(*dirs[k])), dirs[k]->name()), float(ctx.get(*amounts[k]))});
    }

    const float* aoPlane = nullptr;
    if (const BufferPtr ao = ctx.get(ao_)) {
        if (ao->width() != w || ao->height() != h)
            throw Error("input 'ao' is " + std::to_string(ao->width()) + " x " + std::to_string(ao->height()) +
                        " but 'image' is " + std::to_string(w) + " x " + std::to_string(h));
        aoPlane = ao->requireFloat("AO");
    }
    const float ambient = float(ctx.get(ambient_)), diffuse = float(ctx.get(diffuse_));
    const float specular = float(ctx.get(specular_)), shininess = float(ctx.get(shininess_));
    const Color sc = ctx.get(specularColor_);
    const float specColor[3] = {sc.r, sc.g, sc.b};

    auto out = ctx.derive(in, {"R", "G", "B"}, Fill::None);
    float* rgb[3] = {out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B")};
    ctx.parallelFor(0, h, 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                V3f N{nv[0][i], nv[1][i], nv[2][i]};
                const bool lit = isSurface(z[i]) && std::isfinite(N.x) && std::isfinite(N.y) && std::isfinite(N.z);
                if (!lit) {
                    for (int c = 0; c < 3; ++c) rgb[c][i] = albedo[c][i];
                    continue;
                }
                const V3f V = vg.toCamera(vg.position(x, y, z[i]));
                N = normalize(N);
                if (dot(N, V) < 0) N = N * -1.0f;  // two-sided: a back face is lit as its front
                float occlusion = aoPlane ? aoPlane[i] : 1.0f;
                if (!std::isfinite(occlusion)) occlusion = 1.0f;
                float kd = ambient * occlusion, ks = 0;
                for (const Light& l : lights) {
                    const float nl = dot(N, l.toLight);
                    if (nl <= 0) continue;
                    kd += diffuse * l.intensity * nl;
                    const V3f H = normalize(l.toLight + V);
                    const float nh = std::max(0.0f, dot(N, H));
                    if (specular > 0 && nh > 0) ks += specular * l.intensity * std::pow(nh, shininess);
                }
                for (int c = 0; c < 3; ++c) rgb[c][i] = albedo[c][i] * kd + specColor[c] * ks;
            }
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
