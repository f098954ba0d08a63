#include "run_deflate.h"

#include "huffman_lengths.h"

#include <libdeflate.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

namespace darkroom::io {

namespace {

// Input bytes per block: each block gets its own Huffman tables (a header of
// about 60-100 bytes), so smaller blocks follow the picture's regions
// better; this size keeps the headers under 0.1 % of a typical output.
constexpr std::size_t kBlockInput = std::size_t(1) << 17;
// A run shorter than this is written as literals: a length and a distance
// code cost about as many bits as three literals from a skewed histogram.
constexpr std::size_t kMinRun = 4;
constexpr std::size_t kMaxRun = 258;

// A token: a literal byte, or a run (length 3-258 in the low bits, flagged,
// with which of the two distances).
constexpr std::uint32_t kRunFlag = 1u << 16, kPixelDistanceFlag = 1u << 17;

// RFC 1951, 3.2.5: length codes 257-285 and distance codes.
struct LengthCode {
    std::uint16_t symbol, extraBits, extraValue;
};
struct LengthTable {
    std::array<LengthCode, kMaxRun + 1> byLength{};
    LengthTable() {
        static const int base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                     31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
        static const int extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                      2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
        for (int code = 0; code < 29; ++code) {
            const int last = code == 28 ? 258 : (code == 27 ? 257 : base[code + 1] - 1);
            for (int len = base[code]; len <= last; ++len)
                byLength[std::size_t(len)] = {std::uint16_t(257 + code), std::uint16_t(extra[code]),
                                              std::uint16_t(len - base[code])};
        }
    }
};
const LengthTable& lengths() {
    static const LengthTable table;
    return table;
}

// Distances 1-8 (a PNG pixel is at most 8 bytes): codes 0-3 exact, 4 and 5
// with one extra bit.
LengthCode distanceCode(int d) {
    if (d <= 4) return {std::uint16_t(d - 1), 0, 0};
    if (d <= 6) return {4, 1, std::uint16_t(d - 5)};
    return {5, 1, std::uint16_t(d - 7)};
}

// How many bytes from `at` repeat the bytes `distance` before them, up to
// `limit`: 8 bytes compared at a time.
std::size_t runLength(const unsigned char* at, std::size_t distance, std::size_t limit) {
    std::size_t n = 0;
    while (n + 8 <= limit) {
        std::uint64_t a, b;
        std::memcpy(&a, at + n, 8);
        std::memcpy(&b, at + n - distance, 8);
        if (const std::uint64_t x = a ^ b) return n + std::size_t(std::countr_zero(x) / 8);
        n += 8;
    }
    while (n < limit && at[n] == at[n - distance]) ++n;
    return n;
}

struct Histograms {
    std::array<std::uint32_t, 286> litlen{};
    std::array<std::uint32_t, 30> distance{};
    std::uint64_t extraBits = 0;  // of the lengths and distances
};

// One block's tokens and their histograms.
void tokenize(const unsigned char* data, std::size_t begin, std::size_t end, int pixelBytes,
              std::vector<std::uint32_t>& tokens, Histograms& h) {
    const LengthTable& lt = lengths();
    const std::size_t pb = std::size_t(pixelBytes);
    const LengthCode pixelDistance = distanceCode(pixelBytes);
    tokens.clear();
    std::size_t i = begin;
    while (i < end) {
        // Most bytes of a busy region repeat neither neighbour: one compare
        // each decides them.
        const unsigned char c = data[i];
        const bool maybeByte = i >= 1 && c == data[i - 1];
        const bool maybePixel = pb > 1 && i >= pb && c == data[i - pb];
        if (!maybeByte && !maybePixel) {
            tokens.push_back(c);
            ++h.litlen[c];
            ++i;
            continue;
        }
        const std::size_t limit = std::min(kMaxRun, end - i);
        const std::size_t byByte = maybeByte ? runLength(data + i, 1, limit) : 0;
        const std::size_t byPixel = maybePixel && byByte < limit ? runLength(data + i, pb, limit) : 0;
        const std::size_t run = std::max(byByte, byPixel);
        if (run >= kMinRun) {
            const bool pixel = byPixel > byByte;
            tokens.push_back(kRunFlag | (pixel ? kPixelDistanceFlag : 0) | std::uint32_t(run));
            const LengthCode& lc = lt.byLength[run];
            ++h.litlen[lc.symbol];
            ++h.distance[pixel ? pixelDistance.symbol : 0];
            h.extraBits += lc.extraBits + (pixel ? pixelDistance.extraBits : 0);
            i += run;
        } else {
            tokens.push_back(data[i]);
            ++h.litlen[data[i]];
            ++i;
        }
    }
    ++h.litlen[256];  // end of block
}

// LSB-first bit packing at the end of a byte vector. reserve(n) makes room
// for n more bytes, so that put() stores without a capacity check.
class BitWriter {
public:
    explicit BitWriter(std::vector<unsigned char>& out) : out_(out), start_(out.size()), at_(out.size()) {}
    void reserve(std::size_t bytes) { out_.resize(at_ + bytes + 8); }
    void put(std::uint32_t bits, int count) {
        acc_ |= std::uint64_t(bits) << filled_;
        filled_ += count;
        if (filled_ >= 32) {
            const std::uint32_t low = std::uint32_t(acc_);
            unsigned char* p = out_.data() + at_;
            p[0] = static_cast<unsigned char>(low), p[1] = static_cast<unsigned char>(low >> 8);
            p[2] = static_cast<unsigned char>(low >> 16), p[3] = static_cast<unsigned char>(low >> 24);
            at_ += 4;
            acc_ >>= 32;
            filled_ -= 32;
        }
    }
    // Pads with zero bits to the next byte and writes out what is pending.
    void alignToByte() {
        for (; filled_ > 0; filled_ -= 8) {
            out_[at_++] = static_cast<unsigned char>(acc_);
            acc_ >>= 8;
        }
        acc_ = 0;
        filled_ = 0;
    }
    void append(const unsigned char* bytes, std::size_t n) {
        std::memcpy(out_.data() + at_, bytes, n);
        at_ += n;
    }
    // After alignToByte(): drops the unused reserve.
    void finish() { out_.resize(at_); }
    // Bits put since construction (pending ones included).
    std::uint64_t bitsWritten() const { return std::uint64_t(at_ - start_) * 8 + std::uint64_t(filled_); }
    // The first `count` bits of `bits` (LSB first, as put() writes them),
    // from the current bit on; reserve() the bytes first.
    void appendBits(const unsigned char* bits, std::uint64_t count) {
        std::size_t i = 0;
        for (; count >= 32; count -= 32, i += 4)
            put(std::uint32_t(bits[i]) | std::uint32_t(bits[i + 1]) << 8 | std::uint32_t(bits[i + 2]) << 16 |
                    std::uint32_t(bits[i + 3]) << 24,
                32);
        for (; count >= 8; count -= 8, ++i) put(bits[i], 8);
        if (count > 0) put(bits[i] & ((1u << count) - 1u), int(count));
    }

private:
    std::vector<unsigned char>& out_;
    std::size_t start_;
    std::size_t at_;
    std::uint64_t acc_ = 0;
    int filled_ = 0;
};

// The code lengths of both alphabets, run-length coded with symbols 16-18
// (RFC 1951, 3.2.7): each entry is symbol | extra value << 8.
std::vector<std::uint32_t> codeLengthRuns(const std::vector<std::uint8_t>& lens, Histogram19& h) {
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < lens.size();) {
        const std::uint8_t v = lens[i];
        std::size_t n = 1;
        while (i + n < lens.size() && lens[i + n] == v) ++n;
        i += n;
        if (v == 0) {
            for (; n >= 11; n -= std::min<std::size_t>(n, 138))
                out.push_back(18u | std::uint32_t(std::min<std::size_t>(n, 138) - 11) << 8), ++h[18];
            if (n >= 3) out.push_back(17u | std::uint32_t(n - 3) << 8), ++h[17], n = 0;
        } else {
            out.push_back(v), ++h[v], --n;
            for (; n >= 3; n -= std::min<std::size_t>(n, 6))
                out.push_back(16u | std::uint32_t(std::min<std::size_t>(n, 6) - 3) << 8), ++h[16];
        }
        for (; n > 0; --n) out.push_back(v), ++h[v];
    }
    return out;
}

constexpr int kCodeLengthOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
constexpr int kCodeLengthExtra[3] = {2, 3, 7};  // symbols 16, 17, 18

struct BlockPlan {
    HuffmanCode litlen, distance, codeLength;
    std::vector<std::uint32_t> lengthRuns;
    int hlit = 257, hdist = 1, hclen = 4;
    std::uint64_t bits = 0;  // the whole dynamic block, header included
};

int usedPrefix(const std::vector<std::uint8_t>& lengths, int least) {
    int n = int(lengths.size());
    while (n > least && lengths[std::size_t(n - 1)] == 0) --n;
    return n;
}

BlockPlan planBlock(const Histograms& h) {
    BlockPlan b;
    b.litlen = huffmanCode(h.litlen.data(), 286, 15);
    b.distance = huffmanCode(h.distance.data(), 30, 15);
    b.hlit = usedPrefix(b.litlen.lengths, 257);
    b.hdist = usedPrefix(b.distance.lengths, 1);
    std::vector<std::uint8_t> all(b.litlen.lengths.begin(), b.litlen.lengths.begin() + b.hlit);
    all.insert(all.end(), b.distance.lengths.begin(), b.distance.lengths.begin() + b.hdist);
    Histogram19 h19{};
    b.lengthRuns = codeLengthRuns(all, h19);
    b.codeLength = huffmanCode(h19.data(), 19, 7);
    b.hclen = 19;
    while (b.hclen > 4 && b.codeLength.lengths[std::size_t(kCodeLengthOrder[b.hclen - 1])] == 0) --b.hclen;
    b.bits = 3 + 5 + 5 + 4 + 3 * std::uint64_t(b.hclen) + h.extraBits;
    for (int s = 0; s < 19; ++s)
        b.bits += std::uint64_t(h19[std::size_t(s)]) *
                  std::uint64_t(b.codeLength.lengths[std::size_t(s)] + (s >= 16 ? kCodeLengthExtra[s - 16] : 0));
    for (int s = 0; s < 286; ++s) b.bits += std::uint64_t(h.litlen[std::size_t(s)]) * b.litlen.lengths[std::size_t(s)];
    for (int s = 0; s < 30; ++s) b.bits += std::uint64_t(h.distance[std::size_t(s)]) * b.distance.lengths[std::size_t(s)];
    return b;
}

void writeHeader(BitWriter& w, const BlockPlan& b, bool last) {
    w.put(last ? 1u : 0u, 1);
    w.put(2, 2);  // dynamic Huffman codes
    w.put(std::uint32_t(b.hlit - 257), 5);
    w.put(std::uint32_t(b.hdist - 1), 5);
    w.put(std::uint32_t(b.hclen - 4), 4);
    for (int k = 0; k < b.hclen; ++k) w.put(b.codeLength.lengths[std::size_t(kCodeLengthOrder[k])], 3);
    for (const std::uint32_t r : b.lengthRuns) {
        const std::size_t s = r & 0xffu;
        w.put(b.codeLength.codes[s], b.codeLength.lengths[s]);
        if (s >= 16) w.put(r >> 8, kCodeLengthExtra[s - 16]);
    }
}

void writeTokens(BitWriter& w, const BlockPlan& b, const std::vector<std::uint32_t>& tokens, int pixelBytes) {
    const LengthTable& lt = lengths();
    const LengthCode pixelDistance = distanceCode(pixelBytes);
    for (const std::uint32_t t : tokens) {
        if (!(t & kRunFlag)) {
            w.put(b.litlen.codes[t], b.litlen.lengths[t]);
            continue;
        }
        const LengthCode& lc = lt.byLength[t & 0xffffu];
        w.put(b.litlen.codes[lc.symbol], b.litlen.lengths[lc.symbol]);
        if (lc.extraBits) w.put(lc.extraValue, lc.extraBits);
        const LengthCode dc = t & kPixelDistanceFlag ? pixelDistance : LengthCode{0, 0, 0};
        w.put(b.distance.codes[dc.symbol], b.distance.lengths[dc.symbol]);
        if (dc.extraBits) w.put(dc.extraValue, dc.extraBits);
    }
    w.put(b.litlen.codes[256], b.litlen.lengths[256]);
}

// Stored blocks (3.2.4) of at most 65,535 bytes each.
void writeStored(BitWriter& w, const unsigned char* data, std::size_t size, bool last) {
    std::size_t at = 0;
    do {
        const std::size_t n = std::min<std::size_t>(size - at, 65535);
        w.put(last && at + n == size ? 1u : 0u, 1);
        w.put(0, 2);
        w.alignToByte();
        const unsigned char len[4] = {static_cast<unsigned char>(n), static_cast<unsigned char>(n >> 8),
                                      static_cast<unsigned char>(~n), static_cast<unsigned char>(~n >> 8)};
        w.append(len, 4);
        w.append(data + at, n);
        at += n;
    } while (at < size);
}

// One block encoded by itself: its dynamic-Huffman bits from bit 0 of
// `bits`, or `stored` (written by the serial pass: a stored block aligns to
// a byte of the whole stream, which depends on where it lands).
struct EncodedBlock {
    std::vector<unsigned char> bits;
    std::uint64_t bitCount = 0;
    bool stored = false;
};

EncodedBlock encodeBlock(const unsigned char* data, std::size_t begin, std::size_t end, bool last, int pixelBytes) {
    // Each thread keeps its token buffer (a block's worth, 512 KiB).
    static thread_local std::vector<std::uint32_t> tokens;
    tokens.reserve(kBlockInput + 1);
    Histograms h;
    tokenize(data, begin, end, pixelBytes, tokens, h);
    const BlockPlan plan = planBlock(h);
    const std::size_t stored = end - begin;
    const std::uint64_t storedBits = 8 * (stored + 5 * (stored / 65535 + 1)) + 7;
    EncodedBlock out;
    if (plan.bits >= storedBits) {
        out.stored = true;
        return out;
    }
    BitWriter w(out.bits);
    w.reserve(std::size_t(plan.bits / 8) + 16);
    writeHeader(w, plan, last);
    writeTokens(w, plan, tokens, pixelBytes);
    out.bitCount = w.bitsWritten();
    w.alignToByte();
    w.finish();
    return out;
}

}  // namespace

std::vector<unsigned char> runDeflateZlib(const unsigned char* data, std::size_t size, int pixelBytes) {
    pixelBytes = std::clamp(pixelBytes, 1, 8);
    // The blocks are tokenised, planned and coded in parallel, each into
    // bits of its own (their runs may look back into the block before: the
    // input is all there); then joined in order at the bit where each lands.
    // The same stream as coding them one after the other.
    const std::size_t blocks = std::max<std::size_t>(1, (size + kBlockInput - 1) / kBlockInput);
    std::vector<EncodedBlock> coded(blocks);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t k) {
        const std::size_t begin = k * kBlockInput, end = std::min(size, begin + kBlockInput);
        coded[k] = encodeBlock(data, begin, end, k + 1 == blocks, pixelBytes);
    });
    std::vector<unsigned char> out{0x78, 0x01};  // deflate, 32 KiB window, fastest; 0x7801 % 31 == 0 (RFC 1950)
    BitWriter w(out);
    for (std::size_t k = 0; k < blocks; ++k) {
        const std::size_t begin = k * kBlockInput, end = std::min(size, begin + kBlockInput);
        if (coded[k].stored) {
            w.reserve(end - begin + 5 * ((end - begin) / 65535 + 1) + 16);
            writeStored(w, data + begin, end - begin, k + 1 == blocks);
        } else {
            w.reserve(coded[k].bits.size() + 16);
            w.appendBits(coded[k].bits.data(), coded[k].bitCount);
        }
        coded[k] = {};  // its memory back as soon as it is joined
    }
    w.alignToByte();
    const std::uint32_t adler = libdeflate_adler32(1, data, size);
    const unsigned char a[4] = {static_cast<unsigned char>(adler >> 24), static_cast<unsigned char>(adler >> 16),
                                static_cast<unsigned char>(adler >> 8), static_cast<unsigned char>(adler)};
    w.reserve(4);
    w.append(a, 4);
    w.finish();
    return out;
}

}  // namespace darkroom::io
