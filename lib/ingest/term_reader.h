// SPDX-License-Identifier: Apache-2.0
// Finding and reading, in a catalog's netCDF files, the source variables of its vertical
// geometry and surface (heights, formula terms), with the data variables' file and time
// location: a variable with a time dimension is read from the file that holds the data of
// the step asked for, at the data's time index there; one without is read from the data's
// file when it has it, else from the first input file that does.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ingest/input_catalog.h"
#include "ingest/netcdf_file.h"
#include "ingest/vertical_geometry.h"

namespace strielad::ingest {

// A source variable as one input file holds it.
struct TermVariable {
  std::size_t file = 0;  // index into InputCatalog::files
  int grpid = -1, varid = -1;
  std::string name;
  std::vector<std::string> dimensions;  // names, time included
  bool has_time = false;                // its first dimension is the time dimension
  std::size_t time_length = 0;
  std::vector<std::size_t> shape;  // dimension lengths after time
  std::string units;
};

// Every call takes netcdf_mutex() itself. Files stay open until destruction (at most a
// few at a time).
class NcTermReader final : public TermSource {
 public:
  // `catalog` as the files hold it (InputCatalog::as_in_files).
  explicit NcTermReader(InputCatalog catalog);
  ~NcTermReader() override;
  NcTermReader(const NcTermReader&) = delete;
  NcTermReader& operator=(const NcTermReader&) = delete;

  // The variable in the data variables' group (or an ancestor) of the file holding step 0
  // of the data, else of the first input file holding it; nullopt when none does.
  std::optional<TermVariable> find(const std::string& variable);

  // Where `variable` is read for catalog time step `step` (nullopt: time index 0 wherever
  // it is), and its time index there (0 without a time dimension).
  // \error kInvalidInput naming the variable and files: in no input file; with a time
  // dimension but not in the file of the step's data; lacking the step's time index.
  std::pair<TermVariable, std::size_t> locate(const std::string& variable,
                                              std::optional<std::size_t> step);

  std::size_t levels(const std::string& variable) override;
  TermValues read(const std::string& variable, std::optional<std::size_t> step, std::size_t k0,
                  std::size_t k1) override;

  const InputCatalog& catalog() const { return catalog_; }

 private:
  int open_file(std::size_t file);  // caller holds netcdf_mutex()
  std::optional<TermVariable> find_in_file(std::size_t file, const std::string& variable);
  std::optional<TermVariable> find_locked(const std::string& variable);
  std::pair<TermVariable, std::size_t> locate_locked(const std::string& variable,
                                                     std::optional<std::size_t> step);

  InputCatalog catalog_;
  std::string group_;  // the data variables' group ("" for the root)
  std::map<std::size_t, NcFile> open_;
  // (file, variable) pairs known not to exist: each file is searched once per variable.
  std::set<std::pair<std::size_t, std::string>> absent_;
};

}  // namespace strielad::ingest
