#pragma once
// Which Cinema database a product (an image read from one) belongs to: the
// nearest folder at or above it holding a data.csv. Products nest a few
// folders deep (image/<phi>/0.png); a composable image set's buffer names
// the database folder itself. Used to name the database in messages and to
// find the entries a database-wide setting spans (ColorMapping's range).
#include <darkroom/export.h>

#include <string>

namespace darkroom {

// The folder, or "" when no folder within a few levels above holds a data.csv.
DARKROOM_API std::string databaseOfProduct(const std::string& product);

}  // namespace darkroom
