#include "huffman_lengths.h"

#include <algorithm>
#include <numeric>

namespace darkroom::io {

namespace {

// Code lengths of a Huffman tree over the symbols with non-zero weight
// (two-queue construction over the weights sorted ascending).
void huffmanLengths(const std::vector<std::uint64_t>& weight, std::vector<std::uint8_t>& lengths) {
    std::vector<int> order;
    for (int s = 0; s < int(weight.size()); ++s)
        if (weight[std::size_t(s)] > 0) order.push_back(s);
    // Ties by symbol, so the codes do not depend on the sort. (std::sort with
    // a lambda: its helpers stay internal to the library, where stable_sort's
    // buffer rotation is a std:: template on plain ints that the data
    // library's ABI check would find exported.)
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return weight[std::size_t(a)] != weight[std::size_t(b)] ? weight[std::size_t(a)] < weight[std::size_t(b)] : a < b;
    });
    const std::size_t n = order.size();
    // Nodes 0..n-1 are the leaves in ascending order, n.. the merged ones,
    // created in ascending order of weight too.
    std::vector<std::uint64_t> w(2 * n - 1);
    std::vector<int> parent(2 * n - 1, -1);
    for (std::size_t i = 0; i < n; ++i) w[i] = weight[std::size_t(order[i])];
    std::size_t leaf = 0, inner = n, next = n;
    auto take = [&]() -> std::size_t {
        if (leaf < n && (inner >= next || w[leaf] <= w[inner])) return leaf++;
        return inner++;
    };
    for (; next < 2 * n - 1; ++next) {
        const std::size_t a = take(), b = take();
        w[next] = w[a] + w[b];
        parent[a] = parent[b] = int(next);
    }
    std::vector<std::uint8_t> depth(2 * n - 1, 0);
    for (std::size_t i = 2 * n - 1; i-- > 0;)
        if (parent[i] >= 0) depth[i] = std::uint8_t(std::min(255, depth[std::size_t(parent[i])] + 1));
    std::fill(lengths.begin(), lengths.end(), 0);
    for (std::size_t i = 0; i < n; ++i) lengths[std::size_t(order[i])] = depth[i];
}

std::uint16_t reverseBits(std::uint32_t code, int length) {
    std::uint32_t r = 0;
    for (int i = 0; i < length; ++i) r = (r << 1) | ((code >> i) & 1u);
    return std::uint16_t(r);
}

}  // namespace

HuffmanCode huffmanCode(const std::uint32_t* frequencies, int count, int limit) {
    std::vector<std::uint64_t> weight(frequencies, frequencies + count);
    const auto used = std::count_if(weight.begin(), weight.end(), [](std::uint64_t f) { return f > 0; });
    for (int s = 0, missing = int(2 - std::min<long>(used, 2)); missing > 0 && s < count; ++s)
        if (weight[std::size_t(s)] == 0) weight[std::size_t(s)] = 1, --missing;
    HuffmanCode code;
    code.lengths.assign(std::size_t(count), 0);
    for (;;) {
        huffmanLengths(weight, code.lengths);
        if (*std::max_element(code.lengths.begin(), code.lengths.end()) <= limit) break;
        for (auto& f : weight)
            if (f > 0) f = (f + 1) / 2;
    }
    // Canonical codes: shorter codes first, then by symbol (3.2.2).
    std::vector<std::uint32_t> lengthCount(std::size_t(limit) + 1, 0), nextCode(std::size_t(limit) + 2, 0);
    for (auto l : code.lengths)
        if (l) ++lengthCount[l];
    for (int l = 1; l <= limit; ++l)
        nextCode[std::size_t(l) + 1] = (nextCode[std::size_t(l)] + lengthCount[std::size_t(l)]) << 1;
    code.codes.assign(std::size_t(count), 0);
    for (int s = 0; s < count; ++s)
        if (const int l = code.lengths[std::size_t(s)])
            code.codes[std::size_t(s)] = reverseBits(nextCode[std::size_t(l)]++, l);
    return code;
}

}  // namespace darkroom::io
