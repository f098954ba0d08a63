// Image-comparison metrics: see darkroom/accuracy/metrics.h.
#include <darkroom/error.h>
#include <darkroom/accuracy/metrics.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom::metrics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegrees = 180.0 / 3.14159265358979323846;

bool selected(const std::uint8_t* mask, std::size_t i) { return !mask || mask[i] != 0; }

// Sum of (a-b) and (a-b)^2 over usable pixels.
struct DiffSums {
    double sum = 0.0, sumSq = 0.0;
    std::size_t count = 0, skipped = 0;
};

DiffSums diffSums(const float* a, const float* b, std::size_t n, const std::uint8_t* mask) {
    DiffSums s;
    for (std::size_t i = 0; i < n; ++i) {
        if (!selected(mask, i)) continue;
        if (std::isnan(a[i]) || std::isnan(b[i])) {
            ++s.skipped;
            continue;
        }
        const double d = double(a[i]) - double(b[i]);
        s.sum += d;
        s.sumSq += d * d;
        ++s.count;
    }
    return s;
}

void requireSameSize(const Buffer& a, const Buffer& b, const char* what) {
    if (a.width() != b.width() || a.height() != b.height())
        throw Error(std::string(what) + ": images differ in size (" + std::to_string(a.width()) + "x" +
                    std::to_string(a.height()) + " against " + std::to_string(b.width()) + "x" +
                    std::to_string(b.height()) + ")");
}

// Gaussian weights of the 11-tap window, normalised: the 2D window is the outer
// product w[i] w[j] (separable, as fspecial('gaussian', 11, 1.5) normalised).
std::array<double, kSsimWindow> gaussian1d() {
    std::array<double, kSsimWindow> w{};
    double sum = 0.0;
    const int r = kSsimWindow / 2;
    for (int i = 0; i < kSsimWindow; ++i) {
        const double x = i - r;
        w[std::size_t(i)] = std::exp(-x * x / (2.0 * kSsimSigma * kSsimSigma));
        sum += w[std::size_t(i)];
    }
    for (double& v : w) v /= sum;
    return w;
}

// 'valid' separable filtering of a plane (w x h doubles) with the window: the
// result is (w-10) x (h-10).
std::vector<double> filterValid(const std::vector<double>& src, int w, int h,
                                const std::array<double, kSsimWindow>& k) {
    const int ow = w - kSsimWindow + 1, oh = h - kSsimWindow + 1;
    std::vector<double> rows(std::size_t(ow) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < ow; ++x) {
            double s = 0.0;
            const double* p = &src[std::size_t(y) * std::size_t(w) + std::size_t(x)];
            for (int i = 0; i < kSsimWindow; ++i) s += k[std::size_t(i)] * p[i];
            rows[std::size_t(y) * std::size_t(ow) + std::size_t(x)] = s;
        }
    std::vector<double> out(std::size_t(ow) * std::size_t(oh));
    for (int y = 0; y < oh; ++y)
        for (int x = 0; x < ow; ++x) {
            double s = 0.0;
            for (int i = 0; i < kSsimWindow; ++i)
                s += k[std::size_t(i)] * rows[std::size_t(y + i) * std::size_t(ow) + std::size_t(x)];
            out[std::size_t(y) * std::size_t(ow) + std::size_t(x)] = s;
        }
    return out;
}

double percentile(const std::vector<double>& sorted, double p) {
    const double rank = p / 100.0 * double(sorted.size() - 1);
    const std::size_t lo = std::size_t(std::floor(rank));
    const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    const double t = rank - double(lo);
    return sorted[lo] + t * (sorted[hi] - sorted[lo]);
}

}  // namespace

Measure rmse(const float* a, const float* b, std::size_t n, const std::uint8_t* mask) {
    const DiffSums s = diffSums(a, b, n, mask);
    return {s.count ? std::sqrt(s.sumSq / double(s.count)) : kNaN, s.count, s.skipped};
}

Measure psnr(const float* a, const float* b, std::size_t n, double peak, const std::uint8_t* mask) {
    Measure m = rmse(a, b, n, mask);
    if (m.count) m.value = m.value == 0.0 ? std::numeric_limits<double>::infinity() : 20.0 * std::log10(peak / m.value);
    return m;
}

Measure bias(const float* a, const float* b, std::size_t n, const std::uint8_t* mask) {
    const DiffSums s = diffSums(a, b, n, mask);
    return {s.count ? s.sum / double(s.count) : kNaN, s.count, s.skipped};
}

Measure rmse(const Buffer& a, const Buffer& b, std::string_view channel, const std::uint8_t* mask) {
    requireSameSize(a, b, "rmse");
    return rmse(a.requireFloat(channel), b.requireFloat(channel), a.pixelCount(), mask);
}

Measure psnr(const Buffer& a, const Buffer& b, std::string_view channel, double peak, const std::uint8_t* mask) {
    requireSameSize(a, b, "psnr");
    return psnr(a.requireFloat(channel), b.requireFloat(channel), a.pixelCount(), peak, mask);
}

Measure bias(const Buffer& a, const Buffer& b, std::string_view channel, const std::uint8_t* mask) {
    requireSameSize(a, b, "bias");
    return bias(a.requireFloat(channel), b.requireFloat(channel), a.pixelCount(), mask);
}

std::vector<double> ssimMap(const float* a, const float* b, int width, int height, double dynamicRange) {
    if (width < kSsimWindow || height < kSsimWindow) return {};
    const std::size_t n = std::size_t(width) * std::size_t(height);
    // NaN propagates through the filters, marking every window that holds one.
    std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = a[i];
        y[i] = b[i];
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    const auto k = gaussian1d();
    const auto mx = filterValid(x, width, height, k), my = filterValid(y, width, height, k);
    const auto sxx = filterValid(xx, width, height, k), syy = filterValid(yy, width, height, k),
               sxy = filterValid(xy, width, height, k);
    const double c1 = (kSsimK1 * dynamicRange) * (kSsimK1 * dynamicRange);
    const double c2 = (kSsimK2 * dynamicRange) * (kSsimK2 * dynamicRange);
    std::vector<double> out(mx.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double mu1 = mx[i], mu2 = my[i];
        const double s1 = sxx[i] - mu1 * mu1, s2 = syy[i] - mu2 * mu2, s12 = sxy[i] - mu1 * mu2;
        out[i] = ((2.0 * mu1 * mu2 + c1) * (2.0 * s12 + c2)) / ((mu1 * mu1 + mu2 * mu2 + c1) * (s1 + s2 + c2));
    }
    return out;
}

Measure ssim(const float* a, const float* b, int width, int height, double dynamicRange, const std::uint8_t* mask) {
    const std::vector<double> map = ssimMap(a, b, width, height, dynamicRange);
    Measure m;
    if (map.empty()) {
        m.value = kNaN;
        return m;
    }
    const int r = kSsimWindow / 2, ow = width - kSsimWindow + 1, oh = height - kSsimWindow + 1;
    double sum = 0.0;
    for (int j = 0; j < oh; ++j)
        for (int i = 0; i < ow; ++i) {
            const std::size_t centre = std::size_t(j + r) * std::size_t(width) + std::size_t(i + r);
            if (!selected(mask, centre)) continue;
            const double v = map[std::size_t(j) * std::size_t(ow) + std::size_t(i)];
            if (std::isnan(v)) {
                ++m.skipped;
                continue;
            }
            sum += v;
            ++m.count;
        }
    m.value = m.count ? sum / double(m.count) : kNaN;
    return m;
}

Measure ssim(const Buffer& a, const Buffer& b, std::string_view channel, double dynamicRange,
             const std::uint8_t* mask) {
    requireSameSize(a, b, "ssim");
    return ssim(a.requireFloat(channel), b.requireFloat(channel), a.width(), a.height(), dynamicRange, mask);
}

AngularStats angularError(const NormalField& a, const NormalField& b, std::size_t n, const std::uint8_t* mask) {
    AngularStats st;
    std::vector<double> angles;
    angles.reserve(n);
    std::size_t above = 0;
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!selected(mask, i)) continue;
        const double u[3] = {a[0][i], a[1][i], a[2][i]}, v[3] = {b[0][i], b[1][i], b[2][i]};
        bool ok = true;
        for (int c = 0; c < 3; ++c) ok = ok && std::isfinite(u[c]) && std::isfinite(v[c]);
        const double lu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
        const double lv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (!ok || lu == 0.0 || lv == 0.0) {
            ++st.skipped;
            continue;
        }
        const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
        const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        const double deg = std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot) * kDegrees;
        angles.push_back(deg);
        sum += deg;
        if (deg > 5.0) ++above;
    }
    st.count = angles.size();
    if (angles.empty()) {
        st.mean = st.median = st.p95 = st.shareAbove5 = kNaN;
        return st;
    }
    std::sort(angles.begin(), angles.end());
    st.mean = sum / double(st.count);
    st.median = percentile(angles, 50.0);
    st.p95 = percentile(angles, 95.0);
    st.shareAbove5 = double(above) / double(st.count);
    return st;
}

AngularStats angularError(const Buffer& a, const Buffer& b, const std::array<std::string, 3>& channels,
                          const std::uint8_t* mask) {
    requireSameSize(a, b, "angularError");
    const NormalField fa{a.requireFloat(channels[0]), a.requireFloat(channels[1]), a.requireFloat(channels[2])};
    const NormalField fb{b.requireFloat(channels[0]), b.requireFloat(channels[1]), b.requireFloat(channels[2])};
    return angularError(fa, fb, a.pixelCount(), mask);
}

EdgeMasks edgeMasks(const float* depth, const std::uint32_t* ids, int width, int height, double relativeJump) {
    EdgeMasks m;
    m.width = width;
    m.height = height;
    const std::size_t n = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
    m.edge.assign(n, 0);
    m.interior.assign(n, 0);
    auto separated = [&](std::size_t p, std::size_t q) {
        if (ids && ids[p] != ids[q]) return true;
        if (!depth) return false;
        const double zp = depth[p], zq = depth[q];
        const bool fp = std::isfinite(zp), fq = std::isfinite(zq);
        if (fp != fq) return true;
        if (!fp) return false;
        return std::abs(zp - zq) > relativeJump * std::min(zp, zq);
    };
    // Each unordered 8-neighbour pair once: right, down-left, down, down-right.
    const int dx[4] = {1, -1, 0, 1}, dy[4] = {0, 1, 1, 1};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(width) + std::size_t(x);
            for (int d = 0; d < 4; ++d) {
                const int qx = x + dx[d], qy = y + dy[d];
                if (qx < 0 || qx >= width || qy >= height) continue;
                const std::size_t q = std::size_t(qy) * std::size_t(width) + std::size_t(qx);
                if (separated(p, q)) m.edge[p] = m.edge[q] = 1;
            }
        }
    for (std::size_t i = 0; i < n; ++i) {
        const bool valid = !depth || std::isfinite(depth[i]);
        m.interior[i] = (valid && !m.edge[i]) ? 1 : 0;
    }
    return m;
}

EdgeMasks edgeMasks(const Buffer& gbuffer, std::string_view depthChannel, std::string_view idChannel,
                    double relativeJump) {
    const float* depth = gbuffer.requireFloat(depthChannel);
    const std::uint32_t* ids = idChannel.empty() ? nullptr : gbuffer.hostUInt(idChannel);
    return edgeMasks(depth, ids, gbuffer.width(), gbuffer.height(), relativeJump);
}

}  // namespace darkroom::metrics
