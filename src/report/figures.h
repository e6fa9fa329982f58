// The paper's Figs. 2 and 3, computed with the generated kernels.
//
// Fig. 2: billiard collisions (equal masses and radii, the object ball at rest, an
// off-centre hit) for eps = 1, 2/3 and 1/3, simulated with `simulate::run`, both paths
// to scale with the balls drawn at contact. Fig. 3: the scatter angle theta in degrees
// against eps for several v_perp at v_par = 1, and against v_perp for several eps, from
// the generated `scatter_angle` kernel (Eq. 14). Data tables use a fixed number format,
// so regenerating gives the same bytes.
#pragma once

#include "engine/library/library.h"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace impact::report {

/// A figure of the report, plotted with a kernel compiled into Impact (generated from
/// derivations/ when Impact was built).
struct figure {
    std::string name;        ///< `figures/<name>.tex`; its picture `figures/<name>_plot.tex`
    std::string kernel;      ///< the kernel it plots
    std::size_t dimension;   ///< the components of the kernel's vectors (2: the plane); 0 for scalars only
    int paper_number;        ///< its number in the paper (Fig. 2); 0 beyond the paper
    void (*draw)(std::map<std::string, std::string>& files);  ///< adds its files
};

/// The figures Impact draws: the paper's Figs. 2 (billiard, with `collide` in the plane)
/// and 3 (scatter_angle), and the effective tangential restitution of rough spheres
/// (`collide_rough` in the plane).
const std::vector<figure>& all_figures();

/// The figures of a library's report: those whose kernel the library derives (its name,
/// and a vector parameter of as many components). A folder of one's own derivations gets
/// none of the paper's figures, which plot the paper's kernels.
std::vector<figure> figures_of(const engine::library& lib);

/// Every file of `figures`, by path relative to the output folder: `figures/*.dat`; the
/// pgfplots pictures `figures/<name>_plot.tex` (each a tikzpicture reading its tables,
/// sized for the report's text width); and `figures/<name>.tex`, each a complete figure
/// environment with caption and label (fig:billiard, fig:scatter-angle, fig:rough-beta-eff)
/// that includes its picture compiled on its own (`figures/<name>_plot.pdf`, made by
/// `compile_report`), so that the report is compiled without typesetting the plots again.
std::map<std::string, std::string> figure_files(const std::vector<figure>& figures = all_figures());

} // namespace impact::report
