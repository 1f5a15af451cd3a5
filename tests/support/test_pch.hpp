#pragma once
// The tests' precompiled header (tests/CMakeLists.txt): what most test files include, parsed once
// per build instead of once per file. Tests still include what they use themselves.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "scene/scene_reader.hpp"
#include "sim/simulation.hpp"
