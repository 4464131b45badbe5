#pragma once
// `gearloss map --format table` and `--format co2mpas`: loss tables over ratio x speed x
// torque x oil temperature at fixed oil temperatures, and the CO2MPAS form fitted to them
// (gearloss/map/loss_table.hpp, gearloss/map/co2mpas_fit.hpp; docs/tables.md).
#include <string>

#include "commands/common.hpp"
#include "commands/grid_overrides.hpp"

namespace gearloss::app {

struct TableRequest {
    const CommonOptions& common;
    const GridOverrides& grid;
    std::string format;     // "table" or "co2mpas"
    std::string out, json;  // -o (csv or the co2mpas JSON), --json (the table's arrays)
    std::string oil_temps;  // --oil-temps as given (empty: the default axis)
    bool oil_temps_given = false;
    int threads = 0;
    bool stats = false;
};

// The options another format would take that these refuse, then the run: kOk or InputError.
int run_table_format(const TableRequest& q);

}  // namespace gearloss::app
