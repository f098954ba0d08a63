// Sort-last depth compositing time against image size, channel count and
// rank count (docs/scale-out.md). Run under mpirun with 1, 2, 4, ... ranks:
//
//   mpirun -np 4 bench_depth_compositing [--reps N] [--sizes 512x512,1024x1024] [--channels 1,5,9]
//
// Every rank holds a synthetic G-buffer (half its pixels hit at a random
// depth, the others background), as after ray tracing its part of a scene.
// One line per case: the slowest rank's median time of binary swap and of
// MPI_Reduce, the parts of binary swap (exchange, merge, gather at rank 0),
// the bytes a rank sends, and, for scale, a memcpy of one whole image on
// rank 0 in the same process. Before those, rank 0 times the merge rule
// alone on whole images (thread CPU time, so that other processes sharing
// the cores do not count), against a memcpy of the same bytes: the per-pixel
// cost the model in docs/scale-out.md uses.
#include <darkroom/mpi/depth_compositing.h>

#include <algorithm>
#include <ctime>
#include <bit>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace darkroom;
using namespace darkroom::mpi;

namespace {

std::uint32_t hash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    return x ^ (x >> 16);
}

GBufferImage syntheticImage(int rank, int w, int h, int channels) {
    GBufferImage g;
    g.width = w;
    g.height = h;
    g.channels.push_back({"Z", ChannelType::Float32});
    for (int c = 1; c < channels; ++c)
        g.channels.push_back({c == channels - 2   ? std::string("objectId")
                              : c == channels - 1 ? std::string("primitiveId")
                                                  : "field" + std::to_string(c),
                              c >= channels - 2 && channels >= 3 ? ChannelType::UInt32 : ChannelType::Float32});
    const std::size_t n = std::size_t(w) * std::size_t(h);
    g.planes.assign(std::size_t(channels), std::vector<std::uint32_t>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t k = hash(std::uint32_t(i) ^ (std::uint32_t(rank) * 0x9e3779b9u));
        const float z = k & 1 ? 1.0f + float(k >> 8) * 1e-7f : std::numeric_limits<float>::infinity();
        g.planes[0][i] = std::bit_cast<std::uint32_t>(z);
        for (int c = 1; c < channels; ++c) g.planes[std::size_t(c)][i] = k + std::uint32_t(c);
    }
    return g;
}

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string part; std::getline(in, part, sep);) out.push_back(part);
    return out;
}

double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    const Communicator comm(MPI_COMM_WORLD);
    int reps = 7;
    std::vector<std::pair<int, int>> sizes = {{512, 512}, {1024, 1024}, {2048, 2048}, {4096, 2048}};
    std::vector<int> channelCounts = {1, 5, 9};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--reps" && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
        else if (a == "--sizes" && i + 1 < argc) {
            sizes.clear();
            for (const auto& s : split(argv[++i], ',')) {
                const auto wh = split(s, 'x');
                sizes.push_back({std::atoi(wh.at(0).c_str()), std::atoi(wh.at(1).c_str())});
            }
        } else if (a == "--channels" && i + 1 < argc) {
            channelCounts.clear();
            for (const auto& s : split(argv[++i], ',')) channelCounts.push_back(std::atoi(s.c_str()));
        } else {
            if (comm.rank() == 0)
                std::fprintf(stderr, "usage: mpirun -np N %s [--reps N] [--sizes WxH,...] [--channels C,...]\n", argv[0]);
            MPI_Finalize();
            return 2;
        }
    }
    if (comm.rank() == 0) {
        // The merge rule alone: one whole image into another, half the
        // pixels taken (the synthetic images hit on different halves).
        for (const auto& [w, h] : sizes)
            for (int channels : channelCounts) {
                const GBufferImage other = syntheticImage(1, w, h, channels);
                std::vector<std::uint32_t> planar(other.pixelCount() * std::size_t(channels));
                for (std::size_t c = 0; c < other.planes.size(); ++c)
                    std::memcpy(planar.data() + c * other.pixelCount(), other.planes[c].data(), other.pixelCount() * 4);
                std::vector<double> merge, copy;
                std::vector<std::uint32_t> dst(planar.size());
                for (int r = 0; r < reps; ++r) {
                    GBufferImage mine = syntheticImage(0, w, h, channels);
                    double t = cpuSeconds();
                    mergeNearest(mine, 0, mine.pixelCount(), planar.data(), false);
                    merge.push_back(cpuSeconds() - t);
                    t = cpuSeconds();
                    std::memcpy(dst.data(), planar.data(), planar.size() * 4);
                    copy.push_back(cpuSeconds() - t);
                }
                const double px = double(w) * double(h);
                std::printf("MERGE size=%dx%d channels=%d merge_cpu_ms=%.2f ns_per_pixel=%.2f memcpy_cpu_ms=%.2f "
                            "ratio_to_memcpy=%.2f\n",
                            w, h, channels, 1e3 * median(merge), 1e9 * median(merge) / px, 1e3 * median(copy),
                            median(merge) / median(copy));
            }
        std::printf("# ranks=%d reps=%d (slowest rank's median; binary swap parts from the same runs)\n", comm.size(), reps);
    }
    for (const auto& [w, h] : sizes)
        for (int channels : channelCounts) {
            const GBufferImage source = syntheticImage(comm.rank(), w, h, channels);
            const std::size_t bytes = source.pixelCount() * std::size_t(channels) * 4;
            std::vector<double> swap, reduce, exchange, merge, gather, copy;
            std::size_t sent = 0;
            std::vector<std::uint8_t> dst(bytes);
            for (int r = 0; r < reps; ++r) {
                GBufferImage a = source, b = source;
                CompositeStats stats;
                comm.barrier();
                double t = MPI_Wtime();
                compositeByDepth(comm, a, {CompositeAlgorithm::BinarySwap, 0}, &stats);
                swap.push_back(MPI_Wtime() - t);
                exchange.push_back(stats.exchangeSeconds);
                merge.push_back(stats.mergeSeconds);
                gather.push_back(stats.gatherSeconds);
                sent = stats.bytesSent;
                comm.barrier();
                t = MPI_Wtime();
                compositeByDepth(comm, b, {CompositeAlgorithm::Reduce, 0}, nullptr);
                reduce.push_back(MPI_Wtime() - t);
                t = MPI_Wtime();
                for (std::size_t c = 0; c < source.planes.size(); ++c)
                    std::memcpy(dst.data() + c * source.pixelCount() * 4, source.planes[c].data(), source.pixelCount() * 4);
                copy.push_back(MPI_Wtime() - t);
            }
            double mine[6] = {median(swap), median(reduce), median(exchange), median(merge), median(gather), median(copy)};
            double slowest[6];
            MPI_Reduce(mine, slowest, 6, MPI_DOUBLE, MPI_MAX, 0, comm.handle());
            unsigned long long sentMine = sent, sentMax = 0;
            MPI_Reduce(&sentMine, &sentMax, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, 0, comm.handle());
            if (comm.rank() == 0)
                std::printf("RESULT ranks=%d size=%dx%d channels=%d MB=%.1f binary_swap_ms=%.2f reduce_ms=%.2f "
                            "exchange_ms=%.2f merge_ms=%.2f gather_ms=%.2f sent_MB=%.1f memcpy_ms=%.2f\n",
                            comm.size(), w, h, channels, double(bytes) / 1e6, 1e3 * slowest[0], 1e3 * slowest[1],
                            1e3 * slowest[2], 1e3 * slowest[3], 1e3 * slowest[4], double(sentMax) / 1e6,
                            1e3 * mine[5]);
            std::fflush(stdout);
        }
    MPI_Finalize();
    return 0;
}
