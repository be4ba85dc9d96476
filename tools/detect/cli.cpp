// SPDX-License-Identifier: Apache-2.0
// glint-detect's options (docs/tools/glint-detect.md).
#include "cli.h"

#include "glint/core/error.h"
#include "glint/io/envi.h"

namespace glint::tools::detect {

void DetectCli::configure(CLI::App& app) {
    m_app = &app;
    if (CLI::Option* seed = app.get_option_no_throw("--seed")) {
        seed->description("Seed of the noise (default: the input header's 'glint seed', else 1)");
        seed->default_str("");
    }
    app.add_option("input", m_options.input,
                   "Radiometric product (Photons/cm2) of glint-render --radiance-only")
        ->type_name("RADIANCE.img")
        ->required();
    app.add_option("-o,--output", m_options.output, "Output ENVI file (its header beside it)")
        ->type_name("OUT.img")
        ->required();
    app.add_option("--platform", m_options.platform,
                   "The .platform (default: the input header's 'glint platform')")
        ->type_name("FILE");
    app.add_option("--instrument", m_options.instrument,
                   "Instrument of the focal plane, when several have one of that name")
        ->type_name("NAME");
    app.add_option("--focal-plane", m_options.focal_plane,
                   "Focal plane (default: the input header's 'glint focal plane')")
        ->type_name("NAME");
    app.add_option("--qe", m_qe, "Quantum efficiency, electrons per photon, in [0, 1]")
        ->type_name("QE");
    app.add_option("--read-noise", m_read_noise, "Read noise σ in electrons")->type_name("E");
    app.add_option("--dark-current-density", m_dark, "Dark current density in A/m2")
        ->type_name("A_PER_M2");
    app.add_option("--bit-depth", m_bits, "ADC bits, 1 to 32")->type_name("BITS");
    app.add_option("--min-electrons", m_min_e, "Electrons mapped to count 0")->type_name("E");
    app.add_option("--max-electrons", m_max_e, "Electrons mapped to count 2^bits - 1")
        ->type_name("E");
    app.add_option("--integration-time", m_time, "Integration time of one stage in seconds")
        ->type_name("S");
    app.add_option("--data-type", m_data_type,
                   "Output ENVI type (default: the focal plane's <datatype>; float64 with "
                   "--electrons)")
        ->type_name("TYPE");
    app.add_flag("--no-noise", m_options.overrides.no_noise,
                 "No random draws: the mean electrons (signal + dark) through the ADC");
    app.add_flag("--electrons", m_options.overrides.electrons,
                 "Stop before the ADC: write electrons (float64)");
    app.add_option("--mosaic", m_mosaic,
                   "CFA mosaic: bayer, truesense or none (default: the focal plane's "
                   "<channelpattern>)")
        ->type_name("PATTERN");
    app.add_option("--bayer-phase", m_phase,
                   "Bayer layout from the top-left pixel: rggb (default), grbg, gbrg, bggr")
        ->type_name("PHASE");
    app.add_option("--tdi-mode", m_tdi_mode,
                   "TDI accumulation: charge (read noise once, default) or digital (each stage "
                   "read)")
        ->type_name("MODE");
}

int DetectCli::execute(Context& ctx, std::ostream& out) {
    const CLI::App& app = *m_app;
    glint::detect::DetectorOverrides& o = m_options.overrides;
    if (app.count("--qe") > 0) o.quantum_efficiency = m_qe;
    if (app.count("--read-noise") > 0) o.read_noise_e = m_read_noise;
    if (app.count("--dark-current-density") > 0) o.dark_current_density_a_per_m2 = m_dark;
    if (app.count("--bit-depth") > 0) o.bit_depth = m_bits;
    if (app.count("--min-electrons") > 0) o.min_electrons = m_min_e;
    if (app.count("--max-electrons") > 0) o.max_electrons = m_max_e;
    if (app.count("--integration-time") > 0) o.integration_time_s = m_time;
    if (app.count("--data-type") > 0) o.data_type = app_detect::parse_data_type(m_data_type);
    if (app.count("--mosaic") > 0) o.mosaic = app_detect::parse_mosaic(m_mosaic);
    if (app.count("--bayer-phase") > 0) {
        o.bayer_phase = app_detect::parse_bayer_phase(m_phase);
        if (o.mosaic == glint::detect::MosaicChoice::truesense ||
            o.mosaic == glint::detect::MosaicChoice::none) {
            throw usage_error("--bayer-phase applies to Bayer mosaics only");
        }
    }
    if (app.count("--tdi-mode") > 0) o.tdi_mode = app_detect::parse_tdi_mode(m_tdi_mode);
    if (app.count("--seed") > 0) m_options.seed = ctx.seed;
    return app_detect::run(m_options, ctx, out);
}

}  // namespace glint::tools::detect
