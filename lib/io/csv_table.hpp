// The CSV tables a run writes (wall.csv, monitoring.csv, ...), read back:
// numbers under one header row. The report draws them; the error estimate
// compares a run's tables with its coarser twins' and adds columns.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace frostwall::io {

// A CSV file of numbers with one header row; an empty cell is NaN.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> columns;  // columns[c][row]
  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  // nullptr when there is no such column.
  const std::vector<double>* column(const std::string& name) const;
};
CsvTable read_csv(const std::filesystem::path& file);

}  // namespace frostwall::io
