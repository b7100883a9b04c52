#include "io/csv_table.hpp"

#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace frostwall::io {

namespace {

// The cells of one CSV line (no quoting: the run's tables have none).
std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

}  // namespace

const std::vector<double>* CsvTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c] == name) return &columns[c];
  return nullptr;
}

CsvTable read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  CsvTable t;
  std::string line;
  if (!std::getline(in, line)) return t;
  t.header = split_csv_line(line);
  t.columns.resize(t.header.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto cells = split_csv_line(line);
    for (std::size_t c = 0; c < t.header.size(); ++c) {
      double v = std::numeric_limits<double>::quiet_NaN();
      if (c < cells.size() && !cells[c].empty()) {
        try {
          v = std::stod(cells[c]);
        } catch (const std::exception&) {
          throw std::runtime_error(file.string() + ": not a number: '" + cells[c] + "'");
        }
      }
      t.columns[c].push_back(v);
    }
  }
  return t;
}

}  // namespace frostwall::io
