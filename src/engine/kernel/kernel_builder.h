// The builder of a kernel from its `[[kernel]]` (kernel_build.h), its methods spread over
// the files of engine/kernel by what they build: kernel_build.cpp (the kernel, its outputs
// and forms proven, its guards), fixed_kernel.cpp (the kernel of a fixed sphere, in the
// limit of a mass -> +infinity) and kernel_regimes.cpp (its `[[kernel.regime]]`s).
// Internal to engine/kernel.
#pragma once

#include "engine/kernel/kernel_build.h"
#include "engine/prove/prove.h"

#include <ginac/ginac.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace impact::engine {

class kernel_builder {
public:
    kernel_builder(const derivation& d, const resolver& resolve, proof_cache& run)
        : d_(d), resolve_(resolve), run_(run)
    {
    }

    kernel build(const spec::kernel& spec_kernel);

    // fixed_kernel.cpp
    kernel limit_kernel(const kernel& k, const spec::text& mass);

private:
    void check_scale(const kernel_output& o, const spec::text& written) const;
    GiNaC::ex in_kernel(const GiNaC::ex& e) const;
    const kernel_parameter* find_parameter(const kernel& k, const spec::text& name) const;
    kernel_output* find_output(kernel& k, const spec::text& name) const;
    kernel_output make_output(const kernel& k, const spec::kernel_value& output, const spec::kernel& spec_kernel);
    verdict prove_form(const GiNaC::ex& form, const GiNaC::ex& value);
    GiNaC::symbol select_name(const GiNaC::ex& s);
    void require_inputs(const kernel& k, const GiNaC::ex& value, const std::string& member,
                        const source_location& where, const char* what = "output") const;
    kernel_guard make_guard(const kernel& k, const spec::kernel_guard& g);

    // kernel_regimes.cpp
    sampling_regime make_regime(const kernel& k, const spec::sampling_regime& r);
    static std::vector<spec::text> vector_components(const spec::text& written);

    const derivation& d_;
    const resolver& resolve_;
    proof_cache& run_;
    /// Symbols of the results that the kernel computes from its inputs (r = C_M - C_m).
    GiNaC::exmap substitutions_;
    /// Each select met in a form's proof, by the symbol naming its class (`select_name`).
    std::map<GiNaC::ex, GiNaC::symbol, GiNaC::ex_is_less> select_names_;
    std::vector<std::pair<std::vector<GiNaC::ex>, GiNaC::symbol>> select_classes_;
};

} // namespace impact::engine
