#pragma once
// Sort-last depth compositing of G-buffers over the ranks of a communicator.
//
// Every rank holds a G-buffer of the same size and channels, ray traced from
// its own part of the scene. The composite keeps, per pixel, every channel of
// the nearest hit: the rank whose "Z" is smallest gives its Z, scalars,
// normals and ids together, so a pixel never mixes the depth of one hit with
// the field of another.
//
// Ties: at equal Z the hit with the lower (objectId, primitiveId) wins when
// the G-buffer has both uint32 channels, which is the rule the Embree
// capture applies inside one process (capture-embree's nearest_hit_rule.h),
// so a composite of ids made global equals the single-process capture
// whatever the partition. Without ids, or at equal ids (background), the
// lower rank wins. Either way the rule is the minimum of a total order, so
// the result does not depend on the order of the exchanges. Z must not be
// NaN (captures store +inf on background).
//
// Algorithms (docs/scale-out.md has the cost model):
// - BinarySwap: log2(P) rounds in which partners swap halves of the part of
//   the image they own and merge, then a gather of the P pieces at the root.
//   A rank count that is not a power of two is first folded: ranks 2i+1 send
//   their whole image to 2i for i < P - 2^floor(log2 P), keeping each group a
//   contiguous range of ranks so the lower-rank rule still holds.
// - Reduce: MPI_Reduce with a user-defined, non-commutative operator on
//   interleaved pixel records; MPI picks the tree. A baseline to compare with.
#include <darkroom/mpi/communicator.h>
#include <darkroom/mpi/gbuffer_image.h>

#include <cstddef>
#include <memory>

namespace darkroom::mpi {

enum class CompositeAlgorithm { BinarySwap, Reduce };

const char* toString(CompositeAlgorithm a);

struct CompositeOptions {
    CompositeAlgorithm algorithm = CompositeAlgorithm::BinarySwap;
    int root = 0;  // the rank that receives the whole image
};

// Where the time of one composite went, on this rank.
struct CompositeStats {
    double exchangeSeconds = 0;  // sending and receiving image parts (incl. waiting for partners)
    double mergeSeconds = 0;     // comparing depths and copying the nearest hits
    double gatherSeconds = 0;    // collecting the pieces at the root
    std::size_t bytesSent = 0;   // by this rank
};

// Composites `image` (changed in place: it is the working storage) over all
// ranks of `comm`; returns true on the root, whose `image` then holds the
// whole composite, and false elsewhere (their `image` is left partial).
// Collective. Throws darkroom::Error on every rank when the ranks' images
// differ in size or channels, or when there is no "Z" channel.
bool compositeByDepth(const Communicator& comm, GBufferImage& image, const CompositeOptions& options = {},
                      CompositeStats* stats = nullptr);

// The merge rule on one range of pixels, exposed for tests: where `other`
// is nearer (or equally near with lower ids, or equal in both and
// `otherIsLower`), copy all of its channels over `mine`. `other` is planar: channel c of the range starts at
// other + c * count. Returns the number of pixels taken from `other`.
std::size_t mergeNearest(GBufferImage& mine, std::size_t first, std::size_t count, const std::uint32_t* other,
                         bool otherIsLower);

}  // namespace darkroom::mpi
