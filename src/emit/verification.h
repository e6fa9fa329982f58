// The verification report: the accuracy of every emitted kernel, measured.
//
// For each kernel, output and floating-point type: the number of samples, the mean
// and maximum error in ulps against CLN, the worst regime, and the form that was
// chosen, with every candidate's maximum error in double beside it.
#pragma once

#include "verify/choice.h"
#include "verify/proofs.h"

#include <map>
#include <string>
#include <vector>

namespace impact::emit {

/// `output/verification.md`; its banner names `folder`, the derivation files' (engine::source_folder).
/// `of_the_paper` (emit::of_the_paper): its introduction speaks of collisions; else of the
/// kernels of the folder's own derivations. With `z3`, a section on the proofs Z3
/// re-checked: how many it confirmed, per derivation and in all, and each one it did not, with why.
std::string verification_markdown(const std::vector<const verify::kernel_plan*>& plans, const std::string& folder,
                                  bool of_the_paper, const verify::proof_checks* z3 = nullptr);

/// The kernels of each derivation as its web page shows them (report/html.h), by derivation id:
/// each kernel (and its fixed spheres') anchored `kernel-<name>` (`kernel-<name>-fixed-<mass>`),
/// each output's first row `kernel-<name>-<output>`, with the accuracy table of each form.
/// HTML, nothing for a derivation without kernels; under "" the index's summary, each kernel's
/// largest error in each type and form, linked to its section.
std::map<std::string, std::string> verification_html(const std::vector<const engine::derivation*>& derivations,
                                                    const std::vector<const verify::kernel_plan*>& plans);

} // namespace impact::emit
