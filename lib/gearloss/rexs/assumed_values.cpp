// Values of an imported case that REXS does not carry (mapper_internal.hpp, YamlOut::assumed):
// each is written with its reason as a comment and declared in the case's `assumed:` list, which
// the case loader reads (gearloss/case/declared_assumptions.hpp), so `check` and the sidecars of
// map runs list them as they list the loader's own assumed values.
#include "gearloss/rexs/mapper_internal.hpp"

namespace gearloss::rexs::detail {

void YamlOut::assumed(int indent, const std::string& text, const std::string& key, const std::string& reason) {
    line(indent, text, "assumed: " + reason);
    assumed_.emplace_back(key, reason);
}

void YamlOut::write_assumed_list() {
    if (assumed_.empty()) return;
    comment(0, "Values REXS does not carry and the loss model needs, listed by 'gearloss check' and in the sidecars.");
    line(0, "assumed:");
    for (const auto& [key, reason] : assumed_)
        line(2, "- {key: " + key + ", reason: " + quoted(reason, 300) + ", source: REXS import}");
    blank();
}

}  // namespace gearloss::rexs::detail
