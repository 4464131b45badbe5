#pragma once
// Helpers shared by the two halves of the adequacy test (adequacy.cpp: noise and fit;
// adequacy_structure.cpp: structure and combination). Not part of the interface.
#include <cstddef>
#include <vector>

#include "gearloss/diagnosis/adequacy.hpp"

namespace gearloss::diagnosis::adequacy::detail {

using Index = std::vector<std::size_t>;

// Throws std::invalid_argument for a coordinate of the wrong length or a non-finite value.
void check_vector(const std::vector<double>& v, std::size_t n, const char* what, bool may_be_empty);
void check_channel(const Channel& c);
// `idx` sorted by x, ties by index.
void sort_by(Index& idx, const std::vector<double>& x);
// 0, 1, ..., n - 1.
Index all_points(std::size_t n);

}  // namespace gearloss::diagnosis::adequacy::detail
