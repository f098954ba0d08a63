#include "volume_gradient.h"

#include "cell_topology.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace darkroom::volume {
namespace {

using Matrix = std::array<double, 9>;  // row-major 3 x 3

// The inverse of m, or false when m is (nearly) singular relative to its size.
bool invert(const Matrix& m, Matrix& out) {
    const Matrix c = {m[4] * m[8] - m[5] * m[7], m[2] * m[7] - m[1] * m[8], m[1] * m[5] - m[2] * m[4],
                      m[5] * m[6] - m[3] * m[8], m[0] * m[8] - m[2] * m[6], m[2] * m[3] - m[0] * m[5],
                      m[3] * m[7] - m[4] * m[6], m[1] * m[6] - m[0] * m[7], m[0] * m[4] - m[1] * m[3]};
    const double det = m[0] * c[0] + m[1] * c[3] + m[2] * c[6];
    double scale = 0;
    for (double x : m) scale = std::max(scale, std::abs(x));
    if (!(std::abs(det) > 1e-12 * scale * scale * scale)) return false;
    for (int i = 0; i < 9; ++i) out[std::size_t(i)] = c[std::size_t(i)] / det;
    return true;
}

// Image data: the derivative along each grid axis (central differences,
// one-sided on the faces) turned into world units. Positions are
// origin + M (i, j, k) with M = direction * diag(spacing), so the world
// gradient is M^-T times the index-space one.
std::vector<float> imageGradient(const VolumeMesh& v, const std::vector<float>& s,
                                 const std::vector<std::uint8_t>& wanted) {
    const std::size_t nx = std::size_t(v.dims[0]), ny = std::size_t(v.dims[1]), nz = std::size_t(v.dims[2]);
    const std::array<std::size_t, 3> n{nx, ny, nz}, stride{1, nx, nx * ny};
    const Matrix& d = v.direction;
    const Matrix m = {d[0] * v.spacing.x, d[1] * v.spacing.y, d[2] * v.spacing.z,
                      d[3] * v.spacing.x, d[4] * v.spacing.y, d[5] * v.spacing.z,
                      d[6] * v.spacing.x, d[7] * v.spacing.y, d[8] * v.spacing.z};
    Matrix inv{};
    std::vector<float> g(3 * v.pointCount(), 0.0f);
    if (!invert(m, inv)) return g;
    tbb::parallel_for(std::size_t(0), nz, [&](std::size_t k) {
        for (std::size_t j = 0; j < ny; ++j)
            for (std::size_t i = 0; i < nx; ++i) {
                const std::array<std::size_t, 3> at{i, j, k};
                const std::size_t id = i + j * nx + k * nx * ny;
                if (!wanted[id]) continue;
                double index[3];
                for (int a = 0; a < 3; ++a) {
                    const std::size_t lo = at[a] > 0 ? id - stride[a] : id;
                    const std::size_t hi = at[a] + 1 < n[a] ? id + stride[a] : id;
                    const double steps = double((at[a] + 1 < n[a]) + (at[a] > 0));
                    index[a] = (double(s[hi]) - double(s[lo])) / steps;
                }
                for (int a = 0; a < 3; ++a) {
                    const double x = inv[0 * 3 + a] * index[0] + inv[1 * 3 + a] * index[1] + inv[2 * 3 + a] * index[2];
                    g[3 * id + std::size_t(a)] = std::isfinite(x) ? float(x) : 0.0f;
                }
            }
    });
    return g;
}

// The least-squares gradient of a linear fit to the corners, or false for a
// flat cell or one with a NaN value.
bool cellGradient(const VolumeMesh& v, const std::vector<std::uint32_t>& ids, const std::vector<float>& s,
                  Vec3& out) {
    Vec3 c{0, 0, 0};
    double mean = 0;
    for (auto id : ids) c = c + v.point(id), mean += s[id];
    c = c * (1.0 / double(ids.size()));
    mean /= double(ids.size());
    if (!std::isfinite(mean)) return false;
    Matrix a{};
    Vec3 b{0, 0, 0};
    for (auto id : ids) {
        const Vec3 p = v.point(id) - c;
        for (int r = 0; r < 3; ++r)
            for (int q = 0; q < 3; ++q) a[std::size_t(3 * r + q)] += p[r] * p[q];
        b = b + p * (double(s[id]) - mean);
    }
    Matrix inv{};
    if (!invert(a, inv)) return false;
    out = {inv[0] * b.x + inv[1] * b.y + inv[2] * b.z, inv[3] * b.x + inv[4] * b.y + inv[5] * b.z,
           inv[6] * b.x + inv[7] * b.y + inv[8] * b.z};
    return true;
}

// Only the cells around a wanted point are fitted (for one isosurface a
// small share of the volume's: on 663,552 tetrahedra the pass went from
// about 100 to 30 ms).
std::vector<float> unstructuredGradient(const VolumeMesh& v, const std::vector<float>& s,
                                        const std::vector<std::uint8_t>& wanted) {
    const std::size_t np = v.pointCount();
    std::vector<float> out(3 * np, 0.0f);
    std::vector<std::uint32_t> count(np, 0), ids;
    for (std::size_t c = 0; c < v.cellCount(); ++c) {
        const int type = v.cell(c, ids);
        if (!isVolumeCell(type) || linearCell(type).type == 0) continue;
        toLinearCorners(type, ids);
        Vec3 g;
        if (std::none_of(ids.begin(), ids.end(), [&](std::uint32_t id) { return wanted[id] != 0; }) ||
            !cellGradient(v, ids, s, g))
            continue;
        for (auto id : ids) {
            out[3 * id] += float(g.x), out[3 * id + 1] += float(g.y), out[3 * id + 2] += float(g.z);
            ++count[id];
        }
    }
    for (std::size_t i = 0; i < np; ++i)
        for (int a = 0; a < 3 && count[i] > 1; ++a) out[3 * i + std::size_t(a)] /= float(count[i]);
    return out;
}

}  // namespace

std::vector<float> pointGradient(const VolumeMesh& v, const std::vector<float>& scalar,
                                 const std::vector<std::uint8_t>& wanted) {
    return v.isImage() ? imageGradient(v, scalar, wanted) : unstructuredGradient(v, scalar, wanted);
}

}  // namespace darkroom::volume
