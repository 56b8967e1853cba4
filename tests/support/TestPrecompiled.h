// Parsed once per test program (tests/CMakeLists.txt, target_precompile_headers): GoogleTest and the
// standard headers most test files include. Test files still include what they use themselves.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>
