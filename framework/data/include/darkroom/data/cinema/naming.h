#pragma once
// File names of database entries, derived from their parameters so that the
// same parameters always give the same file, in every run and after a resume.
#include <darkroom/export.h>

#include <string>
#include <utility>
#include <vector>

namespace darkroom {

// "phi=30_theta=45" from {{"phi","30"},{"theta","45"}}: name=value pairs
// joined by '_'. Characters outside [A-Za-z0-9.+-] become '~' and a leading
// '.' or '-' of a component is kept only after "name=", so a name never
// starts with '-' or '.' and never contains '/', spaces or shell specials.
// Negative and fractional numbers stay readable: "phi=-22.5". Names longer
// than 200 bytes are cut and end in "~" and a 16-digit hash of the whole name.
DARKROOM_API std::string cinemaEntryName(
    const std::vector<std::pair<std::string, std::string>>& parameters);

}  // namespace darkroom
