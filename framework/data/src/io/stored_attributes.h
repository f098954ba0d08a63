#pragma once
// Which of a buffer's metadata attributes a file keeps. Attributes named
// "run.*" describe the run that made the buffer (CinemaReader's
// "run.selection", the rows a --foreach --where covers), not the picture:
// stored, they would make one entry's file differ between a run over some
// entries and a run over all, and a resume could not keep the files it
// finds. Every writer of attributes (EXR, HDF5) asks here.
#include <string_view>

namespace darkroom {

inline bool isStoredAttribute(std::string_view key) { return key.substr(0, 4) != "run."; }

}  // namespace darkroom
