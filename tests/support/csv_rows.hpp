#pragma once
// A numeric CSV output file (removed.csv, log.csv) read back for tests: its header and rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace mpdem::test {

// The rows of `file` as numbers; its column names into `header`.
inline std::vector<std::vector<double>> csv_rows(const std::filesystem::path& file, std::vector<std::string>& header) {
  std::ifstream in(file);
  std::string line, cell;
  std::getline(in, line);
  std::stringstream hs(line);
  while (std::getline(hs, cell, ',')) header.push_back(cell);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    rows.emplace_back();
    while (std::getline(ls, cell, ',')) rows.back().push_back(std::stod(cell));
  }
  return rows;
}

// The index of column `name` (a test failure when there is none).
inline std::size_t index_of(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << "no column " << name;
  return static_cast<std::size_t>(it - header.begin());
}

}  // namespace mpdem::test
