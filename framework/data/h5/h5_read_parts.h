#pragma once
// Pieces of the .h5 reader (h5_read.cpp): listing a group's datasets and
// checking them, and the `meta` group. Internal.
#include "h5_handle.h"

#include <darkroom/buffer.h>
#include <darkroom/diagnostics.h>

#include <map>
#include <string>
#include <vector>

namespace darkroom::h5 {

// The names of the datasets of a group, in name order (as h5py lists them).
// A link to another file or a soft link is refused (InputError naming
// `where`/name): the reader reads only the file it was given. A sub-group
// is skipped with a warning.
std::vector<std::string> datasetNames(hid_t group, const std::string& where, Diagnostics& warnings);

// What a dataset holds, checked: a simple dataspace of rank 0 to 3, numbers
// or strings, stored in the file itself (no external or virtual storage),
// chunks within --max-decoded-bytes.
struct DatasetInfo {
    int rank = 0;
    hsize_t dims[3] = {1, 1, 1};
    hsize_t elements = 1;
    H5T_class_t typeClass = H5T_NO_CLASS;
    std::size_t typeSize = 0;
    bool unsignedInteger = false;
    bool variableString = false;
};
DatasetInfo inspectDataset(hid_t dataset, const std::string& where);

// The single values of `meta` (numbers of up to 16 elements, strings of one
// element); larger arrays are not read.
struct MetaValuesRead {
    std::map<std::string, std::vector<double>> numbers;
    std::map<std::string, std::string> texts;
};
MetaValuesRead readMeta(hid_t file, const std::string& name, Diagnostics& warnings);

// Puts the camera (CameraPos, CameraDir, CameraUp, CameraHeight or
// CameraAngle) and every other single value into the buffer's metadata;
// warns when `resolution` disagrees with the channels.
void applyMeta(const MetaValuesRead& meta, WritableBuffer& out, const std::string& name, Diagnostics& warnings);

}  // namespace darkroom::h5
