#pragma once
// Where a folder of raylab's files (shaders, exercises) is found at run time, installed or not.
#include <filesystem>

namespace raylab {

// `override` (an environment variable's value) when set and not empty, else
// <exe>/../share/raylab/<name> when it holds `marker`, else `sourceDir`.
std::filesystem::path resourceDirectory(const char* override, const char* name, const char* marker,
                                        const std::filesystem::path& sourceDir);

} // namespace raylab
