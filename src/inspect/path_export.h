#pragma once
// Recorded paths (inspect/path_record.h) as JSON (one object per path, a list of bounces) or CSV
// (one row per bounce), for the viewer's Export buttons and raylab-render --inspect-out.
#include "inspect/path_record.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

nlohmann::json pathsToJson(const std::vector<PathRecord>& paths);
// The inverse of pathsToJson (for tools and tests that read an export back); throws
// nlohmann::json::exception on a malformed document.
std::vector<PathRecord> pathsFromJson(const nlohmann::json& json);
std::string pathsToCsv(const std::vector<PathRecord>& paths);
// By extension: .json or .csv. Throws std::runtime_error naming the file when it cannot write
// or the extension is neither.
void writePaths(const std::filesystem::path& file, const std::vector<PathRecord>& paths);

} // namespace raylab
