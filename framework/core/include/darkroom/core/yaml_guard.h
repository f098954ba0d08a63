#pragma once
// Loading YAML that other people wrote (pipelines, scene files) with the
// checks yaml-cpp does not make. yaml-cpp keeps an alias as a second reference
// to its anchor's node, so loading is linear in the text, but anything that
// walks the result with aliases expanded is not: 674 bytes of nested aliases
// expand to gigabytes, and an alias inside its own anchor makes a cycle that
// a walk never leaves. yaml-cpp also keeps a map's repeated keys (operator[]
// sees the first) and reads only the first of several documents.
#include <darkroom/export.h>

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <string>
#include <vector>

namespace darkroom::yamlguard {

// What aliases may add to a document, beyond its own nodes and text.
inline constexpr std::uint64_t kAliasNodeBudget = 1'000'000;
inline constexpr std::uint64_t kAliasByteBudget = std::uint64_t(64) << 20;

// YAML::Load(text) after checking, in one pass over the parser's events, that
// the text holds one document, that no map repeats a key, that no alias refers
// to a node it is part of, and that aliases expand to at most the budgets
// above. A problem is a YAML::ParserException at its mark (line and column),
// as yaml-cpp's own syntax errors are; its `msg` is a sentence for the user.
DARKROOM_API YAML::Node load(const std::string& text);

}  // namespace darkroom::yamlguard
