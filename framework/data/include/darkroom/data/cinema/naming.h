#pragma once
// File names of database entries, derived from their parameters so that the
// same parameters always give the same file, in every run and after a resume.
#include <darkroom/export.h>

#include <string>
#include <string_view>
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

// One part of such a name (a parameter's name or value) made safe the same
// way: characters outside [A-Za-z0-9.+-] become '~', and so does a leading
// '.' or '-' when `startsName` (the part begins a file name).
DARKROOM_API std::string cinemaNamePart(std::string_view text, bool startsName);

}  // namespace darkroom
