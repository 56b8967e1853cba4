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

// The option and flag names each command's parser takes (-o, --output, --size, … for render).
std::vector<std::string> renderOptionNames();
std::vector<std::string> validateOptionNames();
std::vector<std::string> replayOptionNames();
std::vector<std::string> editOptionNames();
std::vector<std::string> benchOptionNames();
std::vector<std::string> listOptionNames();

}  // namespace rmfx::cli
