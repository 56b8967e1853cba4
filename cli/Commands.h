#pragma once
// The CLI's commands. Each returns the process exit status.

#include <string>
#include <vector>

namespace rmfx::cli {

int renderCommand(const std::vector<std::string>& args);
int validateCommand(const std::vector<std::string>& args);
int replayCommand(const std::vector<std::string>& args);
int editCommand(const std::vector<std::string>& args);
int benchCommand(const std::vector<std::string>& args);
int listCommand(const std::vector<std::string>& args);

}  // namespace rmfx::cli
