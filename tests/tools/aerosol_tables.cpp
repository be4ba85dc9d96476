// SPDX-License-Identifier: Apache-2.0
// Writes data/atmosphere/aerosol_optics.csv: for every OPAC aerosol component and humidity of
// data/atmosphere/aerosol_size_distributions.csv, at every wavelength of
// data/atmosphere/aerosol_refractive_indices.csv up to 20 µm, the size-averaged Mie optics of
// glint/atmosphere/aerosol_optics.h (cross sections, asymmetry, mean particle mass, 32
// Legendre moments, the phase function at 50 angles). scripts/make-aerosol-tables.sh runs it
// over everything (12-17 minutes on 2 cores); the test data/aerosol-tables reruns a few rows
// and compares.
// Usage: aerosol_tables DATA_DIR OUT.csv [COMPONENT:RH ...] [--wavelengths W1,W2,...]
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "glint/atmosphere/aerosol_optics.h"
#include "glint/core/error.h"
#include "glint/core/text.h"

namespace {

using glint::atmosphere::LogNormalSizes;

/// The table's scattering angles, degrees (its p_ columns).
const std::vector<double> kAngles{0,   0.1, 0.2, 0.3, 0.5, 0.7, 1,   1.5, 2,   3,   4,   5,   6,
                                  8,   10,  12,  15,  20,  25,  30,  35,  40,  45,  50,  55,  60,
                                  65,  70,  75,  80,  85,  90,  95,  100, 105, 110, 115, 120, 125,
                                  130, 135, 140, 145, 150, 155, 160, 165, 170, 175, 180};
constexpr int kMoments = 33;  // χ₀ … χ₃₂; the table holds χ₁ … χ₃₂
constexpr double kLongestUm = 20.0;

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw glint::io_error("cannot open", path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The rows of a comma-separated file after its '#' comments and header line.
std::vector<std::vector<std::string>> rows(const std::string& path) {
    std::vector<std::vector<std::string>> out;
    bool header = false;
    const std::string text = read_text(path);
    for (std::string_view line : glint::split_lines(text)) {
        if (line.empty() || line.front() == '#') continue;
        if (!header) {
            header = true;
            continue;
        }
        out.push_back(glint::split_list(line, ','));
    }
    return out;
}

double number(const std::string& s, const std::string& path) {
    const auto v = glint::parse_double(s);
    if (!v) throw glint::input_error("not a number: '" + s + "'", {path, 0, {}});
    return *v;
}

struct Task {
    std::string component;
    int rh = 0;
    double wavelength_um = 0.0;
    LogNormalSizes sizes;
    double density_g_per_cm3 = 0.0;
    double n = 0.0, k = 0.0;
};

std::string format_row(const Task& t, const glint::atmosphere::ParticleOptics& o) {
    std::string line = t.component + "," + std::to_string(t.rh);
    char buf[32];
    auto add = [&](const char* format, double v) {
        std::snprintf(buf, sizeof buf, format, v);
        line += ",";
        line += buf;
    };
    add("%g", t.wavelength_um);
    add("%.6g", o.extinction_um2);
    add("%.6g", o.scattering_um2);
    add("%.6g", o.asymmetry);
    // The mean mass of one particle: its mean volume (µm³ = 1e-12 cm³) × its density.
    add("%.6g", glint::atmosphere::mean_particle_volume_um3(t.sizes) * 1e-12 * t.density_g_per_cm3);
    for (int l = 1; l < kMoments; ++l) add("%.6g", o.legendre[static_cast<std::size_t>(l)]);
    for (double p : o.phase) add("%.6g", p);
    return line;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc < 3) {
            std::fprintf(stderr,
                         "usage: aerosol_tables DATA_DIR OUT.csv [COMPONENT:RH ...] "
                         "[--wavelengths W1,W2,...]\n");
            return 2;
        }
        const std::string data = argv[1];
        const std::string out_path = argv[2];
        std::set<std::pair<std::string, int>> only;
        std::vector<double> wavelengths;
        for (int i = 3; i < argc; ++i) {
            const std::string a = argv[i];
            if (a == "--wavelengths" && i + 1 < argc) {
                for (const std::string& w : glint::split_list(argv[++i], ','))
                    wavelengths.push_back(number(w, "--wavelengths"));
            } else if (const auto colon = a.find(':'); colon != std::string::npos) {
                only.insert({a.substr(0, colon),
                             static_cast<int>(number(a.substr(colon + 1), "COMPONENT:RH"))});
            } else {
                std::fprintf(stderr, "aerosol_tables: unknown argument '%s'\n", a.c_str());
                return 2;
            }
        }
        const std::string size_path = data + "/atmosphere/aerosol_size_distributions.csv";
        const std::string index_path = data + "/atmosphere/aerosol_refractive_indices.csv";
        std::map<std::pair<std::string, int>, std::pair<LogNormalSizes, double>> sizes;
        for (const auto& r : rows(size_path)) {
            if (r.size() != 7) throw glint::input_error("expected 7 columns", {size_path, 0, {}});
            sizes[{r[0], static_cast<int>(number(r[1], size_path))}] = {
                LogNormalSizes{number(r[4], size_path), number(r[5], size_path),
                               number(r[2], size_path), number(r[3], size_path)},
                number(r[6], size_path)};
        }
        std::vector<Task> tasks;
        for (const auto& r : rows(index_path)) {
            if (r.size() != 5) throw glint::input_error("expected 5 columns", {index_path, 0, {}});
            Task t;
            t.component = r[0];
            t.rh = static_cast<int>(number(r[1], index_path));
            t.wavelength_um = number(r[2], index_path);
            t.n = number(r[3], index_path);
            t.k = number(r[4], index_path);
            const auto found = sizes.find({t.component, t.rh});
            if (found == sizes.end()) {
                throw glint::input_error("no size distribution for " + t.component + " " + r[1],
                                         {index_path, 0, {}});
            }
            t.sizes = found->second.first;
            t.density_g_per_cm3 = found->second.second;
            if (t.wavelength_um > kLongestUm + 1e-9) continue;
            if (!only.empty() && !only.contains({t.component, t.rh})) continue;
            if (!wavelengths.empty()) {
                bool wanted = false;
                for (double w : wavelengths)
                    wanted = wanted || std::abs(w - t.wavelength_um) < 1e-9;
                if (!wanted) continue;
            }
            tasks.push_back(t);
        }
        // The costly rows (coarse particles at short wavelengths) spread over the threads by
        // taking tasks in turn; each row is computed alone, so the output does not depend on
        // the number of threads.
        std::vector<std::string> lines(tasks.size());
        std::mutex failure_mutex;
        std::string failure;
        std::size_t next = 0;
        std::mutex next_mutex;
        auto work = [&] {
            for (;;) {
                std::size_t i = 0;
                {
                    std::lock_guard lock(next_mutex);
                    if (next >= tasks.size()) return;
                    i = next++;
                }
                try {
                    const Task& t = tasks[i];
                    lines[i] =
                        format_row(t, glint::atmosphere::size_averaged_optics(
                                          t.sizes, {t.n, t.k}, t.wavelength_um, kAngles, kMoments));
                } catch (const std::exception& e) {
                    std::lock_guard lock(failure_mutex);
                    failure = e.what();
                }
            }
        };
        std::vector<std::thread> threads;
        const unsigned count = std::max(1u, std::thread::hardware_concurrency());
        for (unsigned i = 0; i < count; ++i) threads.emplace_back(work);
        for (std::thread& t : threads) t.join();
        if (!failure.empty()) throw glint::runtime_error(failure);

        std::ofstream out(out_path, std::ios::binary);
        if (!out) throw glint::io_error("cannot write", out_path);
        out << "# glint aerosol optics: OPAC's components "
               "(data/atmosphere/aerosol_size_distributions.csv,\n"
               "# aerosol_refractive_indices.csv) through glint's Mie code, averaged over each "
               "size\n"
               "# distribution (glint/atmosphere/aerosol_optics.h; docs/physics.md, \"Aerosol "
               "optics\").\n"
               "# Written by tests/tools/aerosol_tables.cpp (scripts/make-aerosol-tables.sh); do "
               "not edit.\n"
               "# extinction_um2, scattering_um2: mean cross sections per particle (um^2; 1 "
               "particle per\n"
               "# cm^3 gives 1e-3 of them per km); chi_l: Legendre moments of the phase function\n"
               "# (chi_0 = 1); p_A: the phase function at scattering angle A degrees, int P "
               "dOmega/4pi = 1.\n"
               "# particle_mass_g: the mean mass of one particle as grown at that humidity (its "
               "mean volume\n"
               "# over the size distribution's bounds times the wet density), g.\n";
        out << "component,rh_percent,wavelength_um,extinction_um2,scattering_um2,asymmetry,"
               "particle_mass_g";
        for (int l = 1; l < kMoments; ++l) out << ",chi_" << l;
        for (double a : kAngles) {
            char buf[16];
            std::snprintf(buf, sizeof buf, "%g", a);
            out << ",p_" << buf;
        }
        out << "\n";
        for (const std::string& line : lines) out << line << "\n";
        out.close();
        if (!out) throw glint::io_error("write failed", out_path);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "aerosol_tables: %s\n", e.what());
        return 1;
    }
    return 0;
}
