// The paper's Figs. 2 and 3, computed with the generated kernels.
//
// Fig. 2: billiard collisions (equal masses and radii, the object ball at rest, an
// off-centre hit) for eps = 1, 2/3 and 1/3, simulated with `simulate::run`, both paths
// to scale with the balls drawn at contact. Fig. 3: the scatter angle theta in degrees
// against eps for several v_perp at v_par = 1, and against v_perp for several eps, from
// the generated `scatter_angle` kernel (Eq. 14). Data tables use a fixed number format,
// so regenerating gives the same bytes.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace impact::report {

/// Every figure file, by path relative to the output folder: `figures/*.dat`; the pgfplots
/// pictures `figures/billiard_plot.tex` and `figures/scatter_angle_plot.tex` (each a
/// tikzpicture reading its tables, sized for the report's text width); and
/// `figures/billiard.tex` and `figures/scatter_angle.tex`, each a complete figure
/// environment with caption and label (fig:billiard, fig:scatter-angle) that includes
/// its picture compiled on its own (`figures/<name>_plot.pdf`, made by `compile_report`),
/// so that the report is compiled without typesetting the plots again.
std::map<std::string, std::string> figure_files();

/// The figures' pictures: the `figures/<name>_plot` of each figure, without `.tex`.
std::vector<std::string> figure_pictures();

} // namespace impact::report
