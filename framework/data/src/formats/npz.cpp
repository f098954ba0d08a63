// .npz archives through libzip: each ".npy" member is one array.
#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/input_file.h>
#include <darkroom/limits.h>

#include <fmt/format.h>
#include <zip.h>

#include <cstdio>
#include <memory>

namespace darkroom {

namespace {

struct ZipCloser {
    void operator()(zip_t* z) const { zip_discard(z); }
};
using ZipHandle = std::unique_ptr<zip_t, ZipCloser>;

std::string zipErrorText(int code) {
    zip_error_t e;
    zip_error_init_with_code(&e, code);
    std::string s = zip_error_strerror(&e);
    zip_error_fini(&e);
    return s;
}

ZipHandle openArchive(const std::string& path) {
    requireRegularFile(path, ".npz archive");
    int code = 0;
    zip_t* z = zip_open(path.c_str(), ZIP_RDONLY, &code);
    if (!z)
        throw Error(fmt::format("cannot read '{}': {}; expected an .npz (zip) archive of .npy arrays", path,
                                zipErrorText(code)));
    return ZipHandle(z);
}

std::string memberName(const std::string& file) {
    const std::string suffix = ".npy";
    return file.size() > suffix.size() && file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0
               ? file.substr(0, file.size() - suffix.size())
               : file;
}

// Reads member i. `limit` caps how many bytes are read (headers only need the
// start); a prefix read (`whole` false) returns what there is when the member
// ends or breaks before, so that its header can still be checked.
std::string readMember(zip_t* z, zip_uint64_t i, const std::string& where, std::size_t limit, bool whole = true) {
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat_index(z, i, 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
        throw Error(fmt::format("{}: cannot read the member's size: {}", where, zip_strerror(z)));
    zip_file_t* f = zip_fopen_index(z, i, 0);
    if (!f) throw Error(fmt::format("{}: cannot open the member: {}", where, zip_strerror(z)));
    const std::size_t want = std::min<std::size_t>(limit, st.size);
    std::string bytes(want, '\0');
    std::size_t got = 0;
    while (got < want) {
        const zip_int64_t n = zip_fread(f, bytes.data() + got, want - got);
        if (n < 0 && !whole && got > 0) break;
        if (n < 0) {
            const std::string why = zip_file_strerror(f);
            zip_fclose(f);
            throw Error(fmt::format("{}: the member is corrupt: {}", where, why));
        }
        if (n == 0) break;
        got += std::size_t(n);
    }
    zip_fclose(f);
    if (!whole) bytes.resize(got);
    else if (got != want)
        throw Error(fmt::format("{}: the member ends after {} of {} bytes", where, got, want));
    return bytes;
}

// The member's uncompressed size as the zip directory states it.
std::uint64_t memberSize(zip_t* z, zip_uint64_t i, const std::string& where) {
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat_index(z, i, 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
        throw Error(fmt::format("{}: cannot read the member's size: {}", where, zip_strerror(z)));
    return st.size;
}

// The header, read from the member's start; version 2 and 3 headers may exceed 64 KiB.
NpyHeader memberHeader(zip_t* z, zip_uint64_t i, const std::string& where) {
    constexpr std::size_t kMaxHeader = std::size_t(1) << 24;
    std::string bytes = readMember(z, i, where, 1 << 16, false);
    if (bytes.size() >= 12 && bytes.compare(0, 6, "\x93NUMPY") == 0 && bytes[6] != 1) {
        std::size_t length = 0;
        for (int k = 3; k >= 0; --k) length = (length << 8) | static_cast<unsigned char>(bytes[8 + std::size_t(k)]);
        if (length > kMaxHeader)
            throw InputError(fmt::format("{}: .npy header claims {} bytes; expected at most {}", where, length, kMaxHeader));
        if (12 + length > bytes.size()) bytes = readMember(z, i, where, 12 + length, false);
    }
    return parseNpyHeader(bytes, where);
}

// Before a member is read whole: the zip directory's size must be what the
// header's shape needs, and within the decoded-bytes limit.
void checkMemberSize(const NpyHeader& h, std::uint64_t size, const std::string& where) {
    const std::uint64_t needed = std::uint64_t(h.dataOffset) + h.dataBytes;
    if (size != needed)
        throw InputError(fmt::format("{}: the zip directory gives the member {} bytes, but its header ({} bytes) "
                                     "and shape ({} bytes of values) make {}",
                                     where, size, h.dataOffset, h.dataBytes, needed));
    checkBytes(Limit::DecodedBytes, size, where, "member");
}

template <class Fn>
std::vector<NpyArray> eachMember(const std::string& path, Fn&& fn) {
    const ZipHandle z = openArchive(path);
    const zip_int64_t n = zip_get_num_entries(z.get(), 0);
    std::vector<NpyArray> out;
    for (zip_int64_t i = 0; i < n; ++i) {
        const char* raw = zip_get_name(z.get(), zip_uint64_t(i), 0);
        const std::string name = raw ? raw : "";
        if (name.empty() || name.back() == '/') continue;  // folders
        out.push_back(fn(z.get(), zip_uint64_t(i), path + ":" + name));
        out.back().name = memberName(name);
    }
    if (out.empty()) throw Error(fmt::format("'{}' holds no arrays; expected at least one .npy member", path));
    return out;
}

}  // namespace

std::vector<NpyArray> readNpz(const std::string& path) {
    return eachMember(path, [](zip_t* z, zip_uint64_t i, const std::string& where) {
        checkMemberSize(memberHeader(z, i, where), memberSize(z, i, where), where);
        return parseNpy(readMember(z, i, where, std::size_t(-1)), where);
    });
}

std::vector<NpyArray> readNpzHeaders(const std::string& path) {
    return eachMember(path, [](zip_t* z, zip_uint64_t i, const std::string& where) {
        const NpyHeader h = memberHeader(z, i, where);
        NpyArray a;
        a.descr = h.descr;
        a.shape = h.shape;
        a.fortranOrder = h.fortranOrder;
        return a;
    });
}

void writeNpz(const std::string& path, const std::vector<NpyArray>& arrays, bool compress) {
    if (arrays.empty()) throw Error(fmt::format("cannot write '{}': an .npz needs at least one array", path));
    const std::string tmp = createTemporaryFile(path);
    int code = 0;
    zip_t* z = zip_open(tmp.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
    if (!z) throw Error(fmt::format("cannot write '{}': {}", path, zipErrorText(code)));
    // libzip reads the buffers only at zip_close, so they must outlive the loop.
    std::vector<std::string> payloads;
    payloads.reserve(arrays.size());
    try {
        for (const auto& a : arrays) {
            if (a.values.size() != a.count())
                throw Error(fmt::format("cannot write '{}': array '{}' has {} values, its shape needs {}", path,
                                        a.name, a.values.size(), a.count()));
            payloads.push_back(encodeNpy(a));
            zip_source_t* src = zip_source_buffer(z, payloads.back().data(), payloads.back().size(), 0);
            const zip_int64_t idx = src ? zip_file_add(z, (a.name + ".npy").c_str(), src, ZIP_FL_OVERWRITE) : -1;
            if (idx < 0) {
                if (src) zip_source_free(src);
                throw Error(fmt::format("cannot write '{}': {}", path, zip_strerror(z)));
            }
            zip_set_file_compression(z, zip_uint64_t(idx), compress ? ZIP_CM_DEFLATE : ZIP_CM_STORE, 0);
        }
        if (zip_close(z) != 0) throw Error(fmt::format("cannot write '{}': {}", path, zip_strerror(z)));
    } catch (...) {
        zip_discard(z);
        std::remove(tmp.c_str());
        throw;
    }
    commitFile(tmp, path);
}

}  // namespace darkroom
