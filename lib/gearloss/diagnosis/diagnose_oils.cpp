// diagnose: campaigns that test several oils in one gearbox (a recordings column `oil` naming
// oil files). Oil-independent physics is fitted once; the effects an oil may carry (its
// viscosity data, its friction level) are also offered per oil, so the selection decides, by
// the same evidence as any other effect, whether a term is common or belongs to one oil.
// The recorded differences between oils are set against the model's (what `compare` gives).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <map>

#include "gearloss/diagnosis/diagnose_internal.hpp"
#include "gearloss/case/config.hpp"

namespace gearloss::diagnosis::detail {

CampaignOils campaign_oils(const solver::Model& model, const Recordings& rec) {
    namespace fs = std::filesystem;
    CampaignOils c;
    c.models.push_back(model);
    c.names.push_back("the case's oil (" + model.oil.name + ")");
    // One oil per file: keyed by its resolved path ("B.yaml" and "./B.yaml" are one oil).
    std::map<std::string, int> index, by_path;
    const fs::path dir = fs::path(rec.file).parent_path();
    for (const auto& r : rec.points) {
        if (r.oil.empty()) {
            c.of_point.push_back(0);
            continue;
        }
        auto it = index.find(r.oil);
        if (it == index.end()) {
            const fs::path written(r.oil);
            const fs::path path = written.is_absolute() ? written : dir / written;
            std::error_code ec;
            const fs::path canonical = fs::weakly_canonical(path, ec);
            const std::string key = ec ? path.string() : canonical.string();
            const auto same = by_path.find(key);
            if (same != by_path.end()) {
                it = index.emplace(r.oil, same->second).first;
            } else {
                solver::Model m = model;
                try {
                    io::replace_oil(m, io::load_oil_file(path.string()));
                } catch (const Error& e) {
                    throw InputError(rec.file, r.line, 0, "oil", fmt::format("oil file '{}': {}", r.oil, e.what()));
                }
                c.models.push_back(std::move(m));
                c.names.push_back(r.oil);
                const int j = static_cast<int>(c.models.size()) - 1;
                by_path.emplace(key, j);
                it = index.emplace(r.oil, j).first;
            }
        }
        c.of_point.push_back(it->second);
    }
    return c;
}

void mark_tested(CampaignOils& oils, const Engine& E) {
    oils.tested.assign(oils.models.size(), 0);
    for (const auto& o : E.obs()) oils.tested[static_cast<size_t>(o.oil)] = 1;
}

int CampaignOils::count_tested() const { return static_cast<int>(std::count(tested.begin(), tested.end(), 1)); }

void add_per_oil_candidates(std::vector<Effect>& lib, const CampaignOils& oils) {
    if (oils.count_tested() < 2) return;
    const size_t n = lib.size();
    for (size_t k = 0; k < n; ++k) {
        if (!lib[k].oil_dependent) continue;
        for (size_t j = 0; j < oils.models.size(); ++j)
            if (oils.tested[j]) lib.push_back(for_oil(lib[k], static_cast<int>(j), oils.names[j]));
    }
}

std::vector<OilDifference> oil_differences(const Engine& E, const Pred& before, const Pred& after,
                                           const CampaignOils& oils) {
    std::vector<OilDifference> out;
    if (oils.count_tested() < 2) return out;
    // Points of one operating point (speed and torque within 0.5 %), per oil: mean recorded
    // and predicted losses (replicates averaged).
    struct Sums {
        double rec = 0, b = 0, a = 0;
        int n = 0;
    };
    struct OperatingPoint {
        double w, torque;
        std::map<int, Sums> by_oil;
    };
    std::vector<OperatingPoint> ops;
    for (int i : E.all()) {
        const Obs& o = E.obs()[i];
        auto same = [&](const OperatingPoint& p) {
            return std::abs(p.w - o.w) <= 0.005 * std::max(std::abs(o.w), 1e-9) &&
                   std::abs(p.torque - o.torque) <= 0.005 * std::max(std::abs(o.torque), 1e-9);
        };
        auto it = std::find_if(ops.begin(), ops.end(), same);
        if (it == ops.end()) {
            ops.push_back({o.w, o.torque, {}});
            it = ops.end() - 1;
        }
        Sums& s = it->by_oil[o.oil];
        s.rec += o.loss;
        s.b += before.loss[i];
        s.a += after.loss[i];
        ++s.n;
    }
    for (const auto& p : ops) {
        if (p.by_oil.size() < 2) continue;
        const auto& [ia, A] = *p.by_oil.begin();
        for (const auto& [ib, B] : p.by_oil) {
            if (ib == ia) continue;
            OilDifference d;
            d.speed_rpm = p.w * to_rpm;
            d.torque = p.torque;
            d.oil_a = oils.names[static_cast<size_t>(ia)];  // the first oil tested at this point
            d.oil_b = oils.names[static_cast<size_t>(ib)];
            d.recorded = B.rec / B.n - A.rec / A.n;
            d.model_before = B.b / B.n - A.b / A.n;
            d.model_after = B.a / B.n - A.a / A.n;
            out.push_back(d);
        }
    }
    std::sort(out.begin(), out.end(), [](const OilDifference& x, const OilDifference& y) {
        return std::tie(x.oil_b, x.speed_rpm, x.torque) < std::tie(y.oil_b, y.speed_rpm, y.torque);
    });
    return out;
}

void name_oil_findings(std::vector<Finding>& findings, std::vector<Candidate>& candidates, const std::vector<Effect>& lib) {
    auto per_oil = [&](const std::string& id) -> const Effect* {
        const auto it = std::find_if(lib.begin(), lib.end(), [&](const Effect& e) { return e.id == id; });
        return it != lib.end() && it->oil >= 0 ? &*it : nullptr;
    };
    auto readable = [&](std::string& id) {
        if (const Effect* e = per_oil(id)) id = e->base_id + " (oil " + e->oil_name + ")";
    };
    for (auto& f : findings) {
        for (auto& x : f.equivalent) readable(x);
        if (const Effect* e = per_oil(f.effect)) {
            f.oil = e->oil_name;
            f.effect = e->base_id;
        }
    }
    for (auto& c : candidates) readable(c.effect);
}

}  // namespace gearloss::diagnosis::detail
