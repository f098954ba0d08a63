// Listing and checking the datasets of an .h5 image before anything is read:
// a hostile file must not make the reader follow links out of the file, read
// external raw files, or allocate what its declared sizes ask for.
#include "h5_read_parts.h"

#include <darkroom/error.h>
#include <darkroom/limits.h>

#include <fmt/format.h>

#include <algorithm>

namespace darkroom::h5 {

namespace {

// More links than any image has channels; a file declaring more is refused
// before they are listed.
constexpr hsize_t kMaxLinks = 4096;
constexpr ssize_t kMaxNameBytes = 1024;

std::string linkName(hid_t group, hsize_t i, const std::string& where) {
    const ssize_t n = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (n < 0 || n > kMaxNameBytes)
        throw InputError(fmt::format("{}: link {} has no usable name (expected at most {} bytes)", where, i,
                                     kMaxNameBytes));
    std::string s(std::size_t(n) + 1, '\0');
    if (H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, s.data(), s.size(), H5P_DEFAULT) < 0)
        throw InputError(fmt::format("{}: the name of link {} cannot be read", where, i));
    s.resize(std::size_t(n));
    return s;
}

void checkStorage(hid_t dataset, const DatasetInfo& info, const std::string& where) {
    Handle dcpl(H5Dget_create_plist(dataset), H5Pclose);
    if (!dcpl.valid()) throw InputError(fmt::format("{}: the dataset's storage cannot be read", where));
    if (H5Pget_external_count(dcpl.get()) != 0)
        throw InputError(fmt::format("{}: the values are stored in external files; expected them in the file itself",
                                     where));
    const H5D_layout_t layout = H5Pget_layout(dcpl.get());
    if (layout != H5D_COMPACT && layout != H5D_CONTIGUOUS && layout != H5D_CHUNKED)
        throw InputError(fmt::format("{}: a virtual or unknown storage layout; expected contiguous, compact or "
                                     "chunked storage in the file itself",
                                     where));
    // HDF5 allocates what the file says a dataset's stored bytes are before
    // reading them: a damaged chunk index declaring gigabytes in a small
    // file would be believed (found by fuzz_h5).
    hsize_t fileBytes = 0;
    Handle file(H5Iget_file_id(dataset), H5Fclose);
    const hsize_t stored = H5Dget_storage_size(dataset);
    if (!file.valid() || H5Fget_filesize(file.get(), &fileBytes) < 0 || stored > fileBytes)
        throw InputError(fmt::format("{}: the values are said to take more bytes than the file holds ({}); the file "
                                     "is damaged",
                                     where, fileBytes));
    // Unfiltered storage holds every value: HDF5 1.10 copies a compact
    // dataset's declared size from what it read, however short (fuzz_h5).
    const std::uint64_t declared = info.elements * info.typeSize;
    if ((layout == H5D_COMPACT && stored != declared) || (layout == H5D_CONTIGUOUS && stored != 0 && stored < declared))
        throw InputError(fmt::format("{}: {} bytes stored for {} values of {} bytes; the file is damaged", where,
                                     stored, info.elements, info.typeSize));
    if (layout != H5D_CHUNKED) return;
    hsize_t chunk[32] = {};
    const int rank = H5Pget_chunk(dcpl.get(), 32, chunk);
    if (rank != info.rank) throw InputError(fmt::format("{}: the chunk rank differs from the dataset's", where));
    // HDF5 allocates a whole chunk to decompress it: its size is checked as
    // a decoded array, however small the dataset.
    std::uint64_t bytes = info.typeSize;
    for (int d = 0; d < rank; ++d) {
        // A chunk wider than a fixed-size image serves no writer (h5py and
        // ParaView choose chunks within the extent), and HDF5 1.10 reads out
        // of bounds when such a chunk inflates short (found by fuzz_h5).
        if (chunk[d] == 0 || chunk[d] > std::max<hsize_t>(info.dims[d], 1))
            throw InputError(fmt::format("{}: chunk dimension {} is {}; expected 1 to the dataset's {}", where, d,
                                         chunk[d], info.dims[d]));
        bytes = bytes > (std::uint64_t(1) << 62) / chunk[d] ? std::uint64_t(1) << 62 : bytes * chunk[d];
    }
    checkBytes(Limit::DecodedBytes, bytes, where, "one chunk");
}

}  // namespace

std::vector<std::string> datasetNames(hid_t group, const std::string& where, Diagnostics& warnings) {
    H5G_info_t info{};
    if (H5Gget_info(group, &info) < 0) throw InputError(fmt::format("{}: the group cannot be listed", where));
    if (info.nlinks > kMaxLinks)
        throw InputError(fmt::format("{}: {} entries; expected at most {}", where, info.nlinks, kMaxLinks));
    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.nlinks; ++i) {
        std::string name = linkName(group, i, where);
        H5L_info_t link{};
        if (H5Lget_info(group, name.c_str(), &link, H5P_DEFAULT) < 0)
            throw InputError(fmt::format("{}/{}: the link cannot be read", where, name));
        if (link.type != H5L_TYPE_HARD)
            throw InputError(fmt::format("{}/{}: a soft or external link; expected a dataset in the file itself",
                                         where, name));
        Handle object(H5Oopen(group, name.c_str(), H5P_DEFAULT), H5Oclose);
        if (!object.valid()) throw InputError(fmt::format("{}/{}: the object cannot be opened", where, name));
        if (H5Iget_type(object.get()) != H5I_DATASET) {
            warnings.push_back({Diagnostic::Severity::Warning, where + "/" + name, "not a dataset; skipped", {}});
            continue;
        }
        names.push_back(std::move(name));
    }
    return names;
}

DatasetInfo inspectDataset(hid_t dataset, const std::string& where) {
    DatasetInfo info;
    Handle space(H5Dget_space(dataset), H5Sclose);
    if (!space.valid()) throw InputError(fmt::format("{}: the dataspace cannot be read", where));
    const H5S_class_t spaceClass = H5Sget_simple_extent_type(space.get());
    if (spaceClass != H5S_SCALAR && spaceClass != H5S_SIMPLE)
        throw InputError(fmt::format("{}: an empty (null) dataspace; expected values", where));
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0 || rank > 3)
        throw InputError(fmt::format("{}: {} dimensions; expected at most 3 (rows, columns, components)", where, rank));
    info.rank = rank;
    if (rank > 0 && H5Sget_simple_extent_dims(space.get(), info.dims, nullptr) < 0)
        throw InputError(fmt::format("{}: the dimensions cannot be read", where));
    info.elements = 1;
    for (int d = 0; d < rank; ++d)
        info.elements = info.dims[d] != 0 && info.elements > (hsize_t(1) << 62) / info.dims[d]
                            ? hsize_t(1) << 62
                            : info.elements * info.dims[d];
    Handle type(H5Dget_type(dataset), H5Tclose);
    if (!type.valid()) throw InputError(fmt::format("{}: the datatype cannot be read", where));
    info.typeClass = H5Tget_class(type.get());
    info.typeSize = H5Tget_size(type.get());
    info.unsignedInteger = info.typeClass == H5T_INTEGER && H5Tget_sign(type.get()) == H5T_SGN_NONE;
    info.variableString = info.typeClass == H5T_STRING && H5Tis_variable_str(type.get()) > 0;
    // Numbers as every writer stores them: IEEE floats of 4 or 8 bytes,
    // integers of 1 to 8, every bit used. HDF5 1.10 converts other layouts
    // (a 46,084-byte float) out of bounds (found by fuzz_h5).
    if (info.typeClass == H5T_INTEGER || info.typeClass == H5T_FLOAT) {
        const std::size_t size = info.typeSize;
        const bool sizeOk = info.typeClass == H5T_FLOAT ? size == 4 || size == 8
                                                        : size == 1 || size == 2 || size == 4 || size == 8;
        if (!sizeOk || H5Tget_precision(type.get()) != 8 * size || H5Tget_offset(type.get()) != 0)
            throw InputError(fmt::format("{}: a {} of {} bytes, {} bits used; expected a 4- or 8-byte float or a 1- to "
                                         "8-byte integer using all its bits",
                                         where, info.typeClass == H5T_FLOAT ? "float" : "integer", size,
                                         H5Tget_precision(type.get())));
    }
    checkStorage(dataset, info, where);
    return info;
}

}  // namespace darkroom::h5
