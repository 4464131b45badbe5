#pragma once
// An independent campaign kept as test data: its derived case and recordings under
// tests/data/diagnosis, diagnosed with the default options.
#include <string>

#include "gearloss/diagnosis/diagnose.hpp"
#include "gearloss/diagnosis/recordings.hpp"
#include "test_support.hpp"

namespace test_support {

inline gearloss::diagnosis::Diagnosis diagnose_campaign(const std::string& case_file, const std::string& recordings) {
    const auto c = gearloss::io::load_case(source_path("tests/data/diagnosis/" + case_file));
    return gearloss::diagnosis::diagnose(
        c.model, gearloss::diagnosis::read_recordings(source_path("tests/data/diagnosis/" + recordings)));
}

}  // namespace test_support
