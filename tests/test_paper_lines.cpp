// Every printed line and claim of the paper, typed here from the paper, and whether
// Impact compares it.
//
// The list below is typed from *General Collisions of Smooth Spheres* (not from the
// derivation files): each line of each displayed equation (multi-line equations line by
// line), each equation the text states, each sentence that claims something of the
// results (or of collisions and restitution, in the text's own words), the figure
// captions and the footnotes, in the paper's order, with its place. Sentences that claim
// nothing of collisions are not listed: the paper's plan (Sec. I A), its account of
// others' work ("Eventually Čepič achieved ..."), announcements of what follows ("A more
// intuitive result ... will be derived below", "The derivation is provided in Appendix A")
// and judgements of effort ("The exact magnitude for inelastic collisions is considerably
// more complex").
// A line the derivation files compare must be named, by exactly that place, by the
// `paper` field of some comparison (a printed form of a result or given, or a claim,
// checked or, when no derivation can settle it, `undecided`). A line that cannot be
// compared (the references) says why, and a `[[not_compared]]` of the derivation files
// names it. The test fails when a line listed as compared is not, when one listed as not
// compared is, and when a comparison names a place the list does not have (so the counts
// the errata prints are the paper's).
#define BOOST_TEST_MODULE test_paper_lines
#include <boost/test/unit_test.hpp>

#include "emit/errata.h"
#include "emit/json.h"
#include "emit/latex.h"
#include "emit/terminal.h"
#include "engine/derive/derive.h"
#include "engine/library/library.h"
#include "engine/paper/references.h"
#include "spec/derivation.h"
#include "spec/outline.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace impact;

struct printed_line {
    const char* where;         ///< its place, as the derivation files' `paper` names it
    const char* text;          ///< as printed (equations in LaTeX)
    const char* not_compared;  ///< why it is not compared; nullptr: it must be
};

// clang-format off
const std::vector<printed_line> paper = {
    // The abstract's sentences that claim something of collisions (the others judge the
    // topic's difficulty, cite others' work or announce what follows).
    {"Abstract, 5th sentence", "This method is elaborated and more general by considering transformations to and from a collision-frame.", nullptr},
    {"Abstract, 6th sentence", "The results are extended with a discussion on inelastic collisions, limited to compliance along the common line-of-action.", nullptr},
    {"Abstract, 7th sentence", "The loss of conservation of kinetic energy is circumvented by defining an empirical law relating the change in relative velocities.", nullptr},
    {"Abstract, 8th sentence", "This law has important implications for kinetic energy and relative velocity change due to collision, resulting in classic expressions for general collisions.", nullptr},
    {"Sec. I, assumptions 1 to 3", "Rigid bodies. ... Short collision duration. ... Low velocities.", nullptr},
    {"Sec. I, after the assumptions", "Beyond these assumptions, this paper is limited to cases where the colliding masses are perfectly uniform spheres. The symmetry present in this geometry provides many simplifications for important quantities (e.g. a simplified inertia tensor and limiting the contact surface to a point between the two masses).", nullptr},

    // II A. Collisions along a Line
    {"Sec. II A, before Eq. 1a", "All collisions observe the law of conservation of total energy, but for elastic collisions the kinetic energy is also conserved.", nullptr},
    {"Sec. II A, before Eq. 1a, 2nd sentence", "Inelastic collisions instead see some energy transform due to dissipative or frictive forces.", nullptr},
    {"Eq. 1a", "Mv_M + mv_m = Mv'_M + mv'_m (Momentum)", nullptr},
    {"Eq. 1b", "\\frac{1}{2}Mv_M^2 + \\frac{1}{2}mv_m^2 = \\frac{1}{2}Mv_M'^2 + \\frac{1}{2}mv_m'^2 (Energy)", nullptr},
    {"Sec. II A, before Eq. 2", "A standard result, see for example Morin's theorem 5.3 is the third conserved quantity for 1D collisions. Taking the quotient of the relative momenta and energy quantities indicates that the absolute relative velocity is conserved.", nullptr},
    {"Eq. 2, line 1", "m(v_m - v'_m) = M(v'_M - v_M)", nullptr},
    {"Eq. 2, line 2", "m(v_m^2 - v'_m^2) = M(v_M'^2 - v_M^2)", nullptr},
    {"Eq. 2, right of the brace", "(v_m - v_M) = -(v'_m - v'_M)", nullptr},
    {"Eq. 2, line 3", "\\implies |v_m - v_M| = |v'_m - v'_M|", nullptr},
    {"Sec. II A, after Eq. 2", "Using Eqs. 1a and 2, one can solve this system of two unknowns (v'_m, v'_M) in two equations. Eq. 3 is the general solution for 1D elastic collisions.", nullptr},
    {"Eq. 3, line 1", "v'_M = \\frac{(M-m)v_M + 2mv_m}{M+m}", nullptr},
    {"Eq. 3, line 2", "v'_m = \\frac{(m-M)v_m + 2mv_M}{M+m}", nullptr},
    {"Sec. II A, after Eq. 3, 1st sentence", "Rewriting Eq. 2 as v_m + v'_m = v_M + v'_M reveals the core argument of Čepič's method.", nullptr},
    {"Sec. II A, after Eq. 3, 2nd sentence", "For collisions along a line, the change in velocities due to collisions are equal but opposite for the colliding particles.", nullptr},
    {"Sec. II A, after Eq. 3, 3rd sentence", "This follows from the fact that the change in velocities must follow the line along which the impulses between the masses occur.", nullptr},
    {"Sec. II A, after Eq. 3, 4th sentence", "Clear and immediate implications for higher dimension collisions are present.", nullptr},
    // Its 1st sentence names the figure ("A geometric depiction of the elastic collision of two spheres").
    {"Fig. 1 caption, 2nd sentence", "Subfigure (a) depicts the initial conditions and the forces/displacement at collision.", nullptr},
    {"Fig. 1 caption, 3rd sentence", "Subfigure (b) depicts the initial and final velocities of the spheres.", nullptr},
    {"Fig. 1 caption, 4th sentence", "Subfigure (c) shows the displacement as a function of the sine and cosine of the displacement between the spheres, itself dependent on the rotation of the line-of-action relative to the Cartesian coordinate frame.", nullptr},

    // II B. Collisions along a Plane
    {"Sec. II B, 1st paragraph", "with a component along the parallel of the line-of-action that is affected according to Eq. 2, and a component along the perpendicular", nullptr},
    {"Sec. II B, planar Eq. 2, line 1", "Mv_{M,y} + mv_{m,y} = Mv'_{M,y} + m'_{m,y}, Mv_{M,y} + mv_{m,y} = Mv'_{M,y} + m'_{m,y}", nullptr},
    {"Sec. II B, planar Eq. 2, line 2", "\\frac{1}{2}M(v_{M,x}^2 + v_{M,y}^2) + \\frac{1}{2}m(v_{m,x}^2 + v_{m,y}^2) = \\frac{1}{2}M(v'_{M,x}^2 + v'_{M,y}^2) + \\frac{1}{2}m(v_{m,x}^2 + v_{m,y}^2) (Eq. 2)", nullptr},
    {"Sec. II B, before the display of R", "Given the displacement vector (the line connecting the CoMs of each sphere) r_{mM} = C_M - C_m, a rotation matrix can be constructed using the x- and y-components.", nullptr},
    {"Sec. II B, display of R", "R = (cos θ, sin θ; -sin θ, cos θ) = (r_{mM,x}/||r_{mM}||, r_{mM,y}/||r_{mM}||; -r_{mM,y}/||r_{mM}||, r_{mM,x}/||r_{mM}||)", nullptr},
    {"Footnote 9", "Note that a rotation of axes is a passive transformation, and as such the presented rotation matrix is the transpose (and coincidentally) the inverse of the standard rotation matrix. See 7.", nullptr},
    {"Sec. II B, display of the change of frame", "(v_∥, v_⊥) = R (v_x, v_y) <=> (v_x, v_y) = R^T (v_∥, v_⊥)", nullptr},
    {"Sec. II B, before Eq. 4", "Furthermore, for elastic collisions of smooth spheres, only one of these 1D-axes sees change before and after contact with the other mass.", nullptr},
    {"Sec. II B, before Eq. 4, 2nd and 3rd sentences", "As the spheres collide with point contact, the forces between them act along two perpendicular axes. As only collision forces are responsible for change in velocities, a problem with motion along a plane collapses to one of forces along two lines.", nullptr},
    {"Footnote 10", "The generalisation to collisions in three dimensions is a simple one.", nullptr},
    {"Eq. 4, line 1", "v_M^{(C)'} = (\\frac{(M-m)v_{M,∥} + 2mv_{m,∥}}{M+m}, v_{M,⊥}), v_m^{(C)'} = (\\frac{(m-M)v_{m,∥} + 2Mv_{M,∥}}{m+M}, v_{m,⊥})", nullptr},
    {"Eq. 4, line 2", "v_M^{(L)'} = R^T v_M^{(C)'}, v_m^{(L)'} = R^T v_m^{(C)'}", nullptr},
    {"Sec. II B, after Eq. 4, 1st sentence", "Thus, the collision in planar motion collapses into the relatively simple linear motion case.", nullptr},
    {"Sec. II B, after Eq. 4", "This result extends to higher dimensions also, however, only for spherical objects colliding.", nullptr},

    // III. Inelastic Collisions without Friction
    {"Sec. III, 1st paragraph", "Realistic collisions are not as neatly summarised in a two-liner as Eq. 3. ... Collision restitution laws closely approximating experiment are by necessity empirical.", nullptr},
    {"Sec. III, before Eq. 5", "The first, and most commonly used restitution law is one suggested by Newton himself, introduced as an experimental multiplicative correction to the conservation of relative velocity as Eq. 2", nullptr},
    {"Eq. 5", "\\epsilon = -\\frac{v'_M - v'_m}{v_M - v_m}", nullptr},
    {"Sec. III, 2nd paragraph", "For Newton's ε, the key distinguishing factor is the materials of the colliding objects. Other relevant factors include ...", nullptr},
    {"Sec. III, 3rd paragraph, 1st sentence", "Generally, a coefficient of restitution only describes collisions between two specific objects; it does not generalise.", nullptr},
    {"Sec. III, after Eq. 5", "Newton's coefficient of restitution is defined in the range of ε ∈ [0, 1], with 0 denoting a perfectly inelastic collision and 1 a perfectly elastic.", nullptr},
    {"Sec. III, 4th paragraph", "Newton's restitution law is relevant only for modelling frictional forces along the line of action. Therefore, Čepič's method remains relevant.", nullptr},
    {"Sec. III, 4th paragraph, 3rd sentence", "Modelling dissipative forces along the perpendicular dimensions is considerably more difficult.", nullptr},
    {"Sec. III, before Sec. III A, 1st sentence", "The remaining part of this section focuses on deriving some results related to inelastic collisions using the framework set out in section I.", nullptr},
    {"Sec. III, before Sec. III A", "The standard result of right angle collisions given an elastic collision, also presented in Čepič's paper is shown to be a special case.", nullptr},

    // III A. Derivation of Final Velocities
    {"Sec. III A, 1st paragraph", "The two spheres collide in such a manner, that for each sphere a force is applied from the point of contact, opposite to the direction of motion.", nullptr},
    {"Sec. III A, 1st paragraph, 2nd sentence", "By Newton's third law, a relationship between the change in momenta (before and after contact) and the force applied may be defined; the impulse J.", nullptr},
    {"Eq. 6, line 1", "F = \\frac{dp}{dt} \\iff J = \\int_{t_1}^{t_2} F dt = p' - p", nullptr},
    {"Eq. 6, line 2", "p' = p - J", nullptr},
    {"Eq. 6, line 3", "v' = v - \\frac{1}{m} J", nullptr},
    {"Sec. III A, before Eq. 7", "While the conservation of kinetic energy may no longer hold for inelastic collisions, the change of relative velocities is known to be mediated by an experimentally defined multiplicative correction: Newton's coefficient of restitution ε.", nullptr},
    {"Eq. 7", "(v_M - v_m) = -\\epsilon(v_M - v_m)", nullptr},
    {"Sec. III A, after Eq. 7, 1st sentence", "What remains is a system of three equations in three unknowns, v'_M, v'_m and J.", nullptr},
    {"Sec. III A, after Eq. 7, 2nd sentence", "Note the alternating sign in the term for the impulses correction for masses M and m.", nullptr},
    {"Eq. 8, left, line 1", "v'_{M,∥} = v_{M,∥} - \\frac{1}{M} J", nullptr},
    {"Eq. 8, left, line 2", "v'_{m,∥} = v_{m,∥} + \\frac{1}{m} J", nullptr},
    {"Eq. 8, left, line 3", "(v'_{M,∥} - v'_{m,∥}) = -\\epsilon(v_{M,∥} - v_{m,∥})", nullptr},
    {"Eq. 8, right, line 1", "v'_{M,∥} = \\frac{Mv_{M,∥} + mv_{m,∥} + \\epsilon m(v_{m,∥} - v_{M,∥})}{M+m}", nullptr},
    {"Eq. 8, right, line 2", "v'_{m,∥} = \\frac{mv_{m,∥} + Mv_{M,∥} + \\epsilon M(v_{M,∥} - v_{m,∥})}{M+m}", nullptr},
    {"Eq. 8, right, line 3", "J = -m_{eff}^{-1}(1+\\epsilon)(v_{m,∥} - v_{M,∥})", nullptr},
    {"Sec. III A, after Eq. 8, 1st sentence", "Here the factor m_{eff} denotes the effective mass, defined as m_{eff} = \\frac{1}{m} + \\frac{1}{M} = \\frac{M+m}{mM}.", nullptr},
    {"Sec. III A, after Eq. 8, 2nd sentence", "The final velocities in the elastic collision model, Eq. 4, follow as the special case ε = 1.", nullptr},
    {"Eq. 9", "v'_M = R^T (\\frac{Mv_{M,∥} + mv_{m,∥} + \\epsilon m(v_{m,∥} - v_{M,∥})}{M+m}, v_{M,⊥}), v'_m = R^T (\\frac{Mv_{M,∥} + mv_{m,∥} + \\epsilon M(v_{m,∥} - v_{M,∥})}{M+m}, v_{m,⊥})", nullptr},
    {"Sec. III A, after Eq. 9", "where the superscript (L) denotes the lab frame and (C) the collision frame.", nullptr},

    // III B. Relative Velocity and Kinetic Energy Loss due to Collision
    {"Sec. III B, before Eq. 10", "A key result for the evaluation of the final velocities in the elastic collision case was the conservation of velocity along the line-of-action. It was already given that this would no longer hold for inelastic collisions", nullptr},
    {"Eq. 10, line 1", "\\Delta|v_\\Delta| = (v'_M - v'_m) - (v_M - v_m) = -(\\frac{1}{M} - \\frac{1}{m}) J", nullptr},
    {"Eq. 10, line 2", "= -(1+\\epsilon)(v_m - v_M)", nullptr},
    {"Fig. 2 caption", "Billiard ball collisions with various values for ε (l to r: 3/3, 2/3, 1/3). The left case shows a perfect elastic collision, whereas the other have increasing values for the coefficient of restitution. These plots come from the accompanying Mathematica notebook.", nullptr},
    {"Sec. III B, before Eq. 11, 1st sentence", "The observation that elastic collisions are simply a specific case of inelastic collisions also becomes apparent when considering the change in kinetic energy before and after a collision.", nullptr},
    {"Sec. III B, before Eq. 11", "For elastic collisions, one needs only to invoke the law of conservation of energy to realise that this change is 0.", nullptr},
    {"Eq. 11", "\\Delta|E_K| = E'_{K,∥} - E_{K,∥} = -\\frac{1}{2}(1 - \\epsilon^2)m_{eff}^{-1}(v_m - v_M)^2", nullptr},
    {"Sec. III B, after Eq. 11, 1st sentence", "From the implication of Newton's 0 ≤ ε ≤ 1 implies that ΔE_K ≤ 0; energy is always lost in inelastic collisions.", nullptr},
    {"Sec. III B, after Eq. 11, 2nd sentence", "Again, the limiting case for ε = 1 simply provides Eq. 1b, indicating elastic collisions.", nullptr},
    {"Sec. III B, after Eq. 11, 3rd sentence", "This result is a form of Carnot's 1803 theorem for rigid bodies in translator motion, although limiting cases may have been known much earlier already.", nullptr},

    // III C. Generalised Collisions of Billiard Balls
    {"Sec. III C, 1st paragraph", "Two equal balls are placed on a frictionless surface. ... Otherwise, m = M, r_m = r_M, ||v_M|| = 0.", nullptr},
    {"Sec. III C, before Eq. 12", "a more intuitive result is given by considering the proportion of momentum transferred. Let τ denote the transfer rate, such that", nullptr},
    {"Eq. 12, line 1", "\\tau = \\frac{v'_{1,∥}}{v'_{1,∥} + v'_{2,∥}}", nullptr},
    {"Eq. 12, line 2", "= \\frac{mv_{1,∥} + m\\epsilon v_{1,∥}}{mv_{1,∥} + m\\epsilon v_{1,∥} + mv_{1,∥} - m\\epsilon v_{1,∥}}", nullptr},
    {"Eq. 12, line 3", "= \\frac{v_{1,∥} - \\epsilon v_{1,∥}}{2mv_{1,∥}}", nullptr},
    {"Eq. 12, line 4", "= \\frac{1}{2} - \\frac{1}{2}\\epsilon", nullptr},
    {"Sec. III C, after Eq. 12, 1st sentence", "Again, it is clear collisions occur between one of two extremes.", nullptr},
    {"Sec. III C, after Eq. 12, 2nd sentence", "In the elastic case, 100% of the parallel velocity transfers from the cue ball to the object ball, leaving the first with only its perpendicular velocity.", nullptr},
    {"Sec. III C, after Eq. 12, 3rd sentence", "Juxtaposed to this is the perfectly inelastic case, where the minimum of 50% of the parallel velocity is transferred.", nullptr},
    {"Sec. III C, after Eq. 12, 4th sentence", "This explains why collisions that have the bodies eventually 'stick' together require a ε value of 0; their final parallel velocities are identical", nullptr},
    {"Footnote 11", "Note however that the contrapositive does not hold; collisions where objects do not stick together may still be inelastic, just with some perpendicular velocity remaining. The spheres then continue to move apart.", nullptr},
    {"Sec. III C, after Eq. 12, 5th sentence", "Substituting, Eq. 12 provides a definition of the resultant parallel velocities v'_{M,∥} and v'_{m,∥} solely in terms of the incident parallel velocity v_{m,∥}.", nullptr},
    {"Sec. III C, after Eq. 12, 6th sentence", "Furthermore, the incident velocity of the object ball is set to be 0, such that the eventual final velocities of both balls is a system of two equation in two unknowns.", nullptr},
    {"Sec. III C, before Eq. 13, 1st sentence", "While the fully general case of scattering angles is rather daunting, using the above defined quantities, it can be derived for inelastic billiard collisions.", nullptr},
    {"Sec. III C, before Eq. 13", "Recall the definition of the dot product as the product of the magnitudes of two vectors and the cosine of the angle separating them. Rewritten, the angle between the incident velocities follows as", nullptr},
    {"Eq. 13", "v'_1 \\cdot v'_2 = |v'_1| |v'_2| \\cos θ_{v'_1, v'_2} \\iff θ_{v'_1, v'_2} = \\arccos \\frac{v'_1 \\cdot v'_2}{|v'_1| |v'_2|}", nullptr},
    {"Sec. III C, after Eq. 13, 1st sentence", "The dot-product of the velocities post-collision is simply the product of the parallel components, given the lack of a perpendicular velocity of the object ball.", nullptr},
    {"Sec. III C, after Eq. 13, 2nd sentence", "For the object ball this implies that the final velocity magnitude is entirely dependent on the momentum transferred from the incident cue ball.", nullptr},
    {"Fig. 3 caption, 1st and 2nd sentences", "Plot of the final scatter angle as a function of the pre-collision perpendicular collision and the ε. The parallel incident velocity of the cue ball is set to 1.", nullptr},
    {"Fig. 3 caption, 3rd sentence", "The left graph has lines in order of the incident perpendicular velocity of the cue ball, whose values are to the right of the plot.", nullptr},
    {"Eq. 14, line 1", "θ_{v'_1, v'_2} = \\frac{v'_{1,∥} v'_{2,∥}}{\\sqrt{v'^2_{1,∥} + v'^2_{1,⊥}} \\sqrt{v'^2_{2,∥}}} = \\frac{(\\frac{1}{2} - \\frac{1}{2}\\epsilon)v_{1,∥} \\cdot (\\frac{1}{2} - \\frac{1}{2}\\epsilon)v_{1,∥}}{\\sqrt{((\\frac{1}{2} - \\frac{1}{2}\\epsilon)v_{1,∥})^2 + v_{1,⊥}^2} \\cdot (\\frac{1}{2} + \\frac{1}{2}\\epsilon)v_{1,∥}}", nullptr},
    {"Eq. 14, line 2", "= \\frac{\\frac{1}{2}(1-\\epsilon)v_{1,∥}}{\\frac{1}{2}\\sqrt{((1-\\epsilon)v_{1,∥})^2 + 4v_{1,⊥}^2}} = \\frac{(1-\\epsilon)v_{1,∥}}{\\sqrt{(1-\\epsilon)^2 v_{1,∥}^2 + 4v_{1,⊥}^2}}", nullptr},
    {"Sec. III C, after Eq. 14, 1st sentence", "Eq. 14 gives the scatter angle for a general billiard collision problem as a function of the coefficient of restitution and the incident perpendicular velocity of the first ball.", nullptr},
    {"Sec. III C, after Eq. 14, 2nd sentence", "The standard result of the scatter angle being 90° for all elastic collisions again is a limiting case for ε = 0.", nullptr},
    {"Sec. III C, after Eq. 14, 3rd sentence", "Fig. 3 gives the scatter angle of billiard collisions for an incident parallel velocity of v_{m,∥} = 1.", nullptr},
    {"Sec. III C, after Eq. 14, 4th sentence", "Each curve is limited between 0° and 90° degrees, with the steepness being determined by incident perpendicular velocity.", nullptr},
    {"Sec. III C, after Eq. 14, 5th sentence", "For situations where v_{m,∥} ≫ v_{m,⊥} the scatter angle tends towards 90°, whereas v_{m,∥} ≪ v_{m,⊥} implies tendency towards the minimum of 0°.", nullptr},

    // IV. Conclusion
    // The conclusion's sentences that claim something of the results (the others judge the
    // method, recall others' work or say what the paper leaves out).
    {"Sec. IV, 1st paragraph, 4th sentence", "Inspired by Čepič's recent simple 4 step method, spherical collisions remain simple, even in higher dimensions.", nullptr},
    {"Sec. IV, 1st paragraph, 5th sentence", "While they employed unit-vectors along tangential lines to the collision, here a rotation matrix is used to highlight the proximity to evaluating in the lab-frame.", nullptr},
    {"Sec. IV, 2nd paragraph, 2nd sentence", "With the inclusion of Newton's coefficient of restitution, the transferred velocity in the parallel collision axis may be considered.", nullptr},
    {"Sec. IV, 2nd paragraph, 3rd sentence", "From this, the resultant velocities of both spheres are entirely dependent on the incident velocity of the cue ball.", nullptr},
    {"Sec. IV, 3rd paragraph, 1st sentence", "Another example of the intuition of this method is the constant reminder of special and limiting cases being the well understood elastic and perfectly inelastic collisions.", nullptr},
    {"Sec. IV, 4th paragraph, 2nd and 3rd sentences", "These collisions not only see dissipative forces along the line through the collision point, and can thus consider rotations of the spheres and sliding over each other. While models exist for such collisions, the natural and intuitive measures of a coefficient of restitution and application of conservation laws fall away.", nullptr},

    // Appendix A: Derivation of ΔE_K for inelastic collisions
    {"Appendix A, line 1", "E'_K = \\frac{1}{2}mv'_m + \\frac{1}{2}mv'_M", nullptr},
    {"Appendix A, line 2", "= \\frac{1}{2}m(v_m + \\frac{1}{m}J)^2 + \\frac{1}{2}M(v_M - \\frac{1}{M}J)^2", nullptr},
    {"Appendix A, line 3", "= \\frac{1}{2}m(v_m^2 + 2\\frac{1}{m}v_mJ + \\frac{1}{m^2}J^2) + \\frac{1}{2}M(v_M^2 - 2\\frac{1}{M}v_MJ + \\frac{1}{M^2}J^2)", nullptr},
    {"Appendix A, line 4", "= \\frac{1}{2}mv_m^2 + v_mJ + \\frac{1}{2m}J^2 + \\frac{1}{2}Mv_M^2 - v_MJ + \\frac{1}{2M}J^2", nullptr},
    {"Appendix A, line 5", "= \\frac{1}{2}mv_m^2 + \\frac{1}{2}Mv_M^2 - (v_m - v_M)J + (\\frac{1}{2m} + \\frac{1}{2M})J^2", nullptr},
    {"Appendix A, line 6", "\\rightarrow (\\frac{1}{2m} + \\frac{1}{2M}) = \\frac{2M + 2m}{4mM} = \\frac{1}{2} \\frac{M + m}{mM}", nullptr},
    {"Appendix A, line 7", "\\rightarrow \\frac{M + m}{mM}J^2 = \\frac{M + m}{mM} \\frac{(mM)^2(1 + \\epsilon)^2(v_m - v_M)^2}{(M + m)^2} = \\frac{mM(1 + \\epsilon)^2(v_m - v_M)^2}{M + m}", nullptr},
    {"Appendix A, line 8", "\\rightarrow E_K = \\frac{1}{2}mv_m^2 + \\frac{1}{2}Mv_M^2", nullptr},
    {"Appendix A, line 9", "= E_K - \\frac{mM(1 + \\epsilon)(v_m - v_M)^2}{M + m} + \\frac{1}{2} \\frac{mM(1 + \\epsilon)^2(v_m - v_M)^2}{M + m}", nullptr},
    {"Appendix A, line 10", "= E_K - \\frac{2mM(1 + \\epsilon)(v_m - v_M)^2}{2(M + m)} + \\frac{mM(1 + \\epsilon)^2(v_m - v_M)^2}{2(M + m)}", nullptr},
    {"Appendix A, line 11", "\\rightarrow -2 - 2\\epsilon + (1 + \\epsilon)^2 = -1 + \\epsilon^2 = -(1 - \\epsilon^2)", nullptr},
    {"Appendix A, line 12", "= E_K - (1 - \\epsilon^2) \\frac{mM(v_m - v_M)^2}{2(M + m)}", nullptr},
    {"Appendix A, line 13", "\\Delta E_K = E'_K - E_K = -(1 - \\epsilon^2) \\frac{mM(v_m - v_M)^2}{2(M + m)}", nullptr},

    // The references, after Appendix A: each entry checked against its citations.
    {"Footnote 1", "Bernard Brogliato and B Brogliato. Nonsmooth mechanics. Springer, 1999.", nullptr},
    {"Footnote 2", "Victor BURACU and Aurel ALECU. An extension of carnot's theorem for rigid body collisions. energy, 500:10.", nullptr},
    {"Footnote 3", "Edson Cataldo and Rubens Sampaio. A brief review and a new treatment for rigid bodies collision models. Journal of the Brazilian Society of Mechanical Sciences, 23(1):63–78, 2001.", nullptr},
    {"Footnote 4", "Mojca Čepič. Elastic collisions of smooth spherical objects: Finding final velocities in four simple steps. American Journal of Physics, 87(3):200–207, 2019.", nullptr},
    {"Footnote 5", "Anindya Chatterjee. Rigid body collisions: some general considerations, new collision laws, and some experimental data. Cornell University Ithaca, NY, 1997.", nullptr},
    {"Footnote 6", "Katica R Stevanović Hedrih. Central collision of two rolling balls: theory and examples. Advances in Theoretical and Applied Mechanics, 10(1):33–79, 2017.", nullptr},
    {"Footnote 7", "Bo Lan. A brief guide to the fundamentals of passive and active rotations in material science, 08 2015.", nullptr},
    {"Footnote 8", "David Morin. Introduction to classical mechanics: with problems and solutions. Cambridge University Press, 2008.", nullptr},
    {"Footnote 12", "T Schwager, V Becker, and T Pöschel. Coefficient of tangential restitution for viscoelastic spheres. The European Physical Journal E, 27(1):107–114, 2008.", nullptr},
    {"Footnote 13", "William James Stronge. Impact mechanics. Cambridge university press, 2018.", nullptr},
};
// clang-format on

// Typed from the list above, counted by hand: the paper's printed lines and claims, and
// those Impact compares.
constexpr std::size_t printed_lines_and_claims = 134;
constexpr std::size_t compared = 134;

const engine::library& library()
{
    // The paper's derivations: every file of derivations/ but those beyond the paper (rough
    // spheres and walls, rough_* and wall_*) that hold nothing of it to account, with the
    // derivations they use, and the paper's order of places. (rough_plane compares Sec. IV's
    // "conservation laws fall away" with rough spheres.) The errata they give must be the
    // committed ones (below).
    static const engine::library lib = [] {
        std::vector<spec::derivation> all = engine::read_directory(IMPACT_SOURCE_DIR "/derivations");
        std::set<std::string> wanted;
        for (const spec::derivation& d : all) {
            const std::string name = std::filesystem::path(d.file).filename().string();
            if ((name.rfind("rough_", 0) != 0 && name.rfind("wall_", 0) != 0) || !d.claims.empty() ||
                !d.open_claims.empty() || !d.references.empty())
                wanted.insert(d.id.value);
        }
        for (bool more = true; more;) {   // and what they use, in turn
            more = false;
            for (const spec::derivation& d : all)
                if (wanted.count(d.id.value))
                    for (const spec::use& u : d.uses)
                        more = wanted.insert(u.derivation.value).second || more;
        }
        std::vector<spec::derivation> paper;
        for (spec::derivation& d : all)
            if (wanted.count(d.id.value))
                paper.push_back(std::move(d));
        engine::library l = engine::derive_all(paper);
        l.outline = spec::read_paper_outline(IMPACT_SOURCE_DIR "/derivations");
        return l;
    }();
    return lib;
}

const spec::paper_outline* outline()
{
    return library().outline ? &*library().outline : nullptr;
}

// Every place the derivations' comparisons and undecided claims name, with how many name it.
std::map<std::string, int> compared_places()
{
    std::map<std::string, int> places;
    for (const engine::derivation* d : library().in_order()) {
        for (const engine::paper_comparison& p : d->paper_checks)
            ++places[p.paper];
        for (const engine::text_comparison& t : engine::text_comparisons(d->source))
            ++places[t.paper];
    }
    return places;
}

// The rows of errata.md that name `place` in their first column.
std::vector<std::string> errata_rows_at(const std::string& errata, const std::string& place)
{
    std::vector<std::string> rows;
    std::istringstream lines(errata);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("| " + place + " |", 0) == 0)
            rows.push_back(line);
    return rows;
}

std::string read(const std::string& path)
{
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

BOOST_AUTO_TEST_CASE(the_list_counts_the_paper_s_lines_and_claims)
{
    std::set<std::string> places;
    std::size_t to_compare = 0;
    for (const printed_line& line : paper) {
        BOOST_TEST(places.insert(line.where).second, "listed twice: " << line.where);
        BOOST_TEST(std::string(line.text).size() > 0u, line.where << " has no text");
        if (line.not_compared)
            BOOST_TEST(std::string(line.not_compared).size() > 10u, line.where << " says too little of why");
        else
            ++to_compare;
    }
    BOOST_TEST(paper.size() == printed_lines_and_claims);
    BOOST_TEST(to_compare == compared);
}

BOOST_AUTO_TEST_CASE(every_line_listed_as_compared_is_compared_and_no_other)
{
    const std::map<std::string, int> places = compared_places();
    for (const printed_line& line : paper) {
        const bool is = places.count(line.where) > 0;
        if (line.not_compared)
            BOOST_TEST(!is, line.where << " is listed as not compared (" << line.not_compared
                                      << "), yet a derivation compares it");
        else
            BOOST_TEST(is, line.where << " is printed (\"" << line.text
                                      << "\") and no derivation file compares it: no [[result]], [[given]] "
                                         "or [[claim]] has paper = \"" << line.where << "\"");
    }
    // The lines not compared are those the derivation files name as not compared.
    std::set<std::string> named;
    for (const engine::derivation* d : library().in_order())
        for (const spec::not_compared& line : d->source.uncompared)
            named.insert(line.paper.value);
    for (const printed_line& line : paper)
        BOOST_TEST(named.count(line.where) == (line.not_compared ? 1u : 0u),
                   line.where << (line.not_compared ? " is not compared and no [[not_compared]] names it"
                                                    : " is compared, yet a [[not_compared]] names it"));
    BOOST_TEST(named.size() == static_cast<std::size_t>(printed_lines_and_claims - compared));
    // A comparison whose place the list does not have: a misnamed place, or a line the
    // list lacks.
    std::set<std::string> listed;
    for (const printed_line& line : paper)
        listed.insert(line.where);
    for (const auto& [place, count] : places)
        BOOST_TEST(listed.count(place) == 1u, count << " comparison(s) name \"" << place
                                                    << "\", a place not in the paper's list");
}

BOOST_AUTO_TEST_CASE(the_errata_the_report_and_the_paper_page_state_the_count)
{
    const std::vector<const engine::derivation*> all = library().in_order();
    BOOST_TEST(emit::compared_places(all) == compared);
    const std::string errata = emit::errata_markdown(all, outline());
    BOOST_TEST(errata.find(fmt::format("{} printed lines and claims of the paper, {} of them compared",
                                       printed_lines_and_claims, compared)) != std::string::npos);
    const emit::paper_count n = emit::count_paper(all);
    BOOST_TEST(n.lines == printed_lines_and_claims);
    BOOST_TEST(n.compared == compared);
    // The committed output says the same, and docs/paper.md gives both counts.
    BOOST_TEST((read(IMPACT_SOURCE_DIR "/output/errata.md") == errata),
               "output/errata.md is not what the derivations give: run impact regenerate");
    const std::string page = read(IMPACT_SOURCE_DIR "/docs/paper.md");
    BOOST_TEST(page.find(fmt::format("{} printed lines and claims", printed_lines_and_claims)) != std::string::npos,
               "docs/paper.md does not give the count of printed lines and claims");
    BOOST_TEST(page.find(fmt::format("{} of them are compared", compared)) != std::string::npos,
               "docs/paper.md does not give the count compared");
}

// derivations/paper_order.txt orders the errata as the paper prints its lines. It lists
// the places of the list above, in its order (two transcriptions of the paper agree), and
// the rows of errata.md, and of the report's table, follow it.
BOOST_AUTO_TEST_CASE(the_errata_lists_its_rows_in_the_paper_s_order)
{
    BOOST_REQUIRE(outline());
    std::vector<std::string> in_file, typed;
    for (const spec::text& place : outline()->places)
        in_file.push_back(place.value);
    std::map<std::string, std::size_t> position;
    for (const printed_line& line : paper) {
        position.emplace(line.where, typed.size());
        typed.push_back(line.where);
    }
    BOOST_TEST(in_file == typed, boost::test_tools::per_element());

    const std::string errata = emit::errata_markdown(library().in_order(), outline());
    std::istringstream rows(errata.substr(errata.find("| --- |")));
    std::string row;
    std::getline(rows, row);
    std::size_t count = 0, last = 0;
    std::string last_place;
    while (std::getline(rows, row) && row.rfind("| ", 0) == 0) {
        const std::string place = row.substr(2, row.find(" | ") - 2);
        BOOST_REQUIRE_MESSAGE(position.count(place) == 1, "a row at \"" << place << "\", not in the paper's list");
        BOOST_TEST(position[place] >= last, "\"" << place << "\" comes after \"" << last_place << "\"");
        last = position[place];
        last_place = place;
        ++count;
    }
    BOOST_TEST(count == emit::count_paper(library().in_order()).rows);
    // The report's table starts where the paper does, with the abstract (whose claims are
    // compared by derivations that come later in the library's order).
    BOOST_TEST(emit::latex_errata(library().in_order(), outline()).rows.rfind("Abstract, 5th sentence (Sect.", 0) == 0u);
    BOOST_TEST(emit::latex_errata(library().in_order()).rows.rfind("Abstract, 5th sentence (Sect.", 0) != 0u);
}

BOOST_AUTO_TEST_CASE(every_comparison_s_verdict_is_settled)
{
    // Compared means proven to agree or to disagree: a sampled or undecided verdict on a
    // printed line is no comparison a reader can trust.
    for (const engine::derivation* d : library().in_order())
        for (const engine::paper_comparison& p : d->paper_checks)
            BOOST_TEST((p.agreement.what == engine::verdict::status::proven ||
                        p.agreement.what == engine::verdict::status::failed),
                       d->id() << ": " << p.paper << ", " << p.subject << " is " << engine::to_string(p.agreement));
}

BOOST_AUTO_TEST_CASE(a_claim_no_derivation_settles_is_one_row_undecided_never_disagrees)
{
    const std::string errata = emit::errata_markdown(library().in_order());
    // Typed from the paper: Sec. III's first paragraph speaks of experiment, and Sec. I's
    // assumptions of real bodies; one row each, undecided.
    for (const char* place : {"Sec. III, 1st paragraph", "Sec. I, assumptions 1 to 3"}) {
        const std::vector<std::string> rows = errata_rows_at(errata, place);
        BOOST_TEST(rows.size() == 1u, place);
        for (const std::string& row : rows) {
            BOOST_TEST(row.find("**undecided**") != std::string::npos, row);
            BOOST_TEST(row.find("disagrees") == std::string::npos, row);
        }
    }
    // Every line is compared: Fig. 1(b)'s sentence as the geometry a drawing of the final
    // velocities shows, the references against their citations (below).
    BOOST_TEST(errata.find("Not compared") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(each_reference_is_a_row_checked_against_its_citations)
{
    // Typed from the paper's list of references and its text: every entry is cited (4 by
    // Čepič's name, 5 by Chatterjee's, 8 by Morin's, 12 by Schwager's, 13 by Stronge's; 2
    // and 6 together, for Carnot's theorem; 7 in Footnote 9). Entry 1 names Brogliato twice
    // ("Bernard Brogliato and B Brogliato") and entry 2 prints no year ("energy, 500:10"):
    // those two disagree, the others agree.
    const std::string errata = emit::errata_markdown(library().in_order());
    for (int n : {1, 2, 3, 4, 5, 6, 7, 8, 12, 13}) {
        const std::vector<std::string> rows = errata_rows_at(errata, fmt::format("Footnote {}", n));
        BOOST_TEST_REQUIRE(rows.size() == 1u, n);
        const std::string& row = rows.front();
        BOOST_TEST(row.find("| reference |") != std::string::npos, row);
        const bool faulty = n == 1 || n == 2;
        BOOST_TEST((row.find("**disagrees**") != std::string::npos) == faulty, row);
        BOOST_TEST((row.find("| agrees |") != std::string::npos) == !faulty, row);
    }
    // Each row shows its entry as the list above types it from the paper.
    for (const printed_line& line : paper)
        if (std::string(line.where).rfind("Footnote ", 0) == 0 && errata_rows_at(errata, line.where).size() == 1 &&
            errata_rows_at(errata, line.where).front().find("| reference |") != std::string::npos)
            BOOST_TEST(errata_rows_at(errata, line.where).front().find(std::string("| ") + line.text + " |") !=
                           std::string::npos,
                       line.where);
    BOOST_TEST(errata_rows_at(errata, "Footnote 1").front().find("names one author twice (Bernard Brogliato and B "
                                                                 "Brogliato)") != std::string::npos);
    BOOST_TEST(errata_rows_at(errata, "Footnote 2").front().find("prints no year") != std::string::npos);
    BOOST_TEST(errata_rows_at(errata, "Footnote 4").front().find("Sec. I A (beside Čepič)") != std::string::npos);
    BOOST_TEST(errata_rows_at(errata, "Footnote 7").front().find("cited at Footnote 9") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(each_claim_is_a_row_and_one_misprint_in_several_components_is_one)
{
    const std::string errata = emit::errata_markdown(library().in_order());
    // Typed from the paper: the 5th sentence after Eq. 14 makes two claims (90 degrees for
    // v_par >> v_perp, 0 degrees for v_par << v_perp) with its two limits swapped: one
    // misprint, one row that disagrees, one finding: theta = atan(2 v_perp / ((1 - eps) v_par))
    // tends to 0 degrees as v_perp -> 0 and to 90 degrees as v_perp grows.
    const std::vector<std::string> swapped = errata_rows_at(errata, "Sec. III C, after Eq. 14, 5th sentence");
    BOOST_TEST_REQUIRE(swapped.size() == 1u);
    BOOST_TEST(swapped.front().find("**disagrees**") != std::string::npos, swapped.front());
    BOOST_TEST(swapped.front().find("| the values are swapped: $\\theta$ is $0^\\circ$ for $v_{1,\\perp} \\to 0$ and "
                                    "$90^\\circ$ for $v_{1,\\perp} \\to \\infty$ |") != std::string::npos,
               swapped.front());
    // Before Eq. 12, typed from the paper: "the proportion of momentum transferred. Let tau
    // denote the transfer rate, tau = v'_1/(v'_1 + v'_2)": that is the share the cue ball keeps.
    // Either edit mends it, the complement or the velocities swapped: said as alternatives.
    const std::vector<std::string> share = errata_rows_at(errata, "Sec. III C, before Eq. 12");
    BOOST_TEST_REQUIRE(share.size() == 1u);
    BOOST_TEST(share.front().find("| it holds with $1 - \\tau$ for $\\tau$; or $v'_{1,\\parallel}$ and "
                                  "$v'_{2,\\parallel}$ swapped |") != std::string::npos,
               share.front());
    // The 2nd sentence: 90 degrees is the elastic limit, eps = 1, not eps = 0: that one change.
    const std::vector<std::string> elastic = errata_rows_at(errata, "Sec. III C, after Eq. 14, 2nd sentence");
    BOOST_TEST_REQUIRE(elastic.size() == 1u);
    BOOST_TEST(elastic.front().find("| it holds for $\\epsilon \\to 1$ instead |") != std::string::npos,
               elastic.front());
    // Claims about the angle in degrees (90 and 0 degrees) are answered in the angle, not
    // its cosine, and in degrees, as the paper states them.
    for (const char* place : {"Sec. III C, after Eq. 14, 5th sentence", "Sec. III C, after Eq. 14, 2nd sentence"})
        for (const std::string& row : errata_rows_at(errata, place)) {
            BOOST_TEST(row.find("\\theta") != std::string::npos, row);
            BOOST_TEST(row.substr(row.find("| checked: ")).find("90^\\circ$") != std::string::npos, row);
            BOOST_TEST(row.find("\\pi") == std::string::npos, row);
            BOOST_TEST(row.find("\\cos") == std::string::npos, row);
        }
    // Eq. 9 prints v'_m with the sign of eps M (v_M - v_m) turned, once in the collision
    // frame and so in both lab components: one misprint, one row that disagrees.
    std::size_t disagree = 0;
    for (const std::string& row : errata_rows_at(errata, "Eq. 9"))
        disagree += row.find("**disagrees**") != std::string::npos ? 1 : 0;
    BOOST_TEST(disagree == 1u);
    // A claim's row shows what was checked, not the value of one side.
    for (const std::string& row : errata_rows_at(errata, "Sec. III C, after Eq. 14, 2nd sentence"))
        BOOST_TEST(row.find("checked: ") != std::string::npos, row);
}

BOOST_AUTO_TEST_CASE(the_claims_checked_of_one_quote_are_one_finding)
{
    const std::string errata = emit::errata_markdown(library().in_order());
    // Typed from the paper: Fig. 2's caption gives eps as 3/3, 2/3, 1/3 from left to right
    // and calls them "increasing"; checked panel against panel, neither step increases, each
    // decreases: one misprint, one row that disagrees, both checks shown, each reversed.
    const std::vector<std::string> caption = errata_rows_at(errata, "Fig. 2 caption");
    BOOST_TEST_REQUIRE(caption.size() == 1u);
    BOOST_TEST(caption[0].find("**disagrees**") != std::string::npos, caption[0]);
    BOOST_TEST(caption[0].find("\\frac{2}{3} > 1") != std::string::npos, caption[0]);
    BOOST_TEST(caption[0].find("\\frac{1}{3} > \\frac{2}{3}") != std::string::npos, caption[0]);
    BOOST_TEST(caption[0].find("the reverse holds in each check: $\\frac{2}{3} < 1$ and $\\frac{1}{3} < "
                               "\\frac{2}{3}$") != std::string::npos,
               caption[0]);
    // Appendix A, line 6 prints 1/(2m) + 1/(2M) = (2M + 2m)/(4mM) = 1/2 (M + m)/(mM): each
    // member checked against the first, one row, both proven, the quote shown once.
    const std::vector<std::string> line_6 = errata_rows_at(errata, "Appendix A, line 6");
    BOOST_TEST_REQUIRE(line_6.size() == 1u);
    BOOST_TEST(line_6[0].find("both proven") != std::string::npos, line_6[0]);
    BOOST_TEST(line_6[0].find("4 m M") != std::string::npos, line_6[0]);
    BOOST_TEST(line_6[0].find("\\frac{1}{2} (M + m)") != std::string::npos, line_6[0]);
    const std::string quote = "\\frac{2M + 2m}{4mM}";
    BOOST_TEST(line_6[0].find(quote) == line_6[0].rfind(quote), line_6[0]);
}

BOOST_AUTO_TEST_CASE(eq14_prints_the_angle_where_its_cosine_belongs)
{
    // Typed from the paper: Eq. 14's first line sets theta equal to v'_1 . v'_2 / (|v'_1| |v'_2|),
    // which Eq. 13 gives as its cosine: the misprint is there, once. The sentence after it,
    // that Eq. 14 gives the scatter angle as a function of eps and v_perp, then holds: the
    // angle is the arccosine of Eq. 14's last member.
    const std::string errata = emit::errata_markdown(library().in_order());
    bool found = false;
    for (const std::string& row : errata_rows_at(errata, "Eq. 14, line 1"))
        found = found || (row.find("| **disagrees** |") != std::string::npos &&
                          row.find("it holds with $\\cos\\theta$ for $\\theta$") != std::string::npos);
    BOOST_TEST(found);
    for (const std::string& row : errata_rows_at(errata, "Sec. III C, after Eq. 14, 1st sentence")) {
        BOOST_TEST(row.find("| agrees |") != std::string::npos, row);
        BOOST_TEST(row.find("\\arccos") != std::string::npos, row);
    }
}

BOOST_AUTO_TEST_CASE(the_angle_of_eq13_is_between_the_final_velocities_not_the_incident_ones)
{
    // Typed from the paper: "Rewritten, the angle between the incident velocities follows as"
    // Eq. 13, whose velocities are primed (final); the object ball is at rest before the
    // collision, so its incident velocity makes no angle.
    const std::string errata = emit::errata_markdown(library().in_order());
    const std::vector<std::string> rows = errata_rows_at(errata, "Sec. III C, before Eq. 13");
    BOOST_TEST_REQUIRE(rows.size() == 1u);
    BOOST_TEST(rows[0].find("| **disagrees** |") != std::string::npos, rows[0]);
    BOOST_TEST(rows[0].find("derived, $\\|\\mathbf{v}_2\\| = 0$") != std::string::npos, rows[0]);
}

BOOST_AUTO_TEST_CASE(every_agreeing_claim_shows_what_was_proven_in_its_derivation_s_section)
{
    // The report's errata table refers a claim whose check is too wide for its cell to the
    // derivation's section ("checked in Sect. ..."): the check must be there, inline or
    // displayed, never a bare "agrees".
    std::size_t claims = 0;
    for (const engine::derivation* d : library().in_order()) {
        std::istringstream lines(emit::latex_fragment(*d));
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("\\item ", 0) != 0 || line.find(", claim: ") == std::string::npos ||
                line.find("--- agrees") == std::string::npos)
                continue;
            ++claims;
            // A claim the paper says does not hold agrees refuted (Sec. III C's steepness).
            BOOST_TEST((line.find("(proven: ") != std::string::npos || line.find("; proven:") != std::string::npos ||
                        line.find("; refuted, as the paper says:") != std::string::npos ||
                        line.find("(refuted, as the paper says: ") != std::string::npos),
                       d->id() << ": " << line);
        }
    }
    BOOST_TEST(claims > 50u);
}

BOOST_AUTO_TEST_CASE(each_agreeing_row_says_how_agreement_was_established)
{
    const std::string errata = emit::errata_markdown(library().in_order());
    std::size_t agreeing = 0;
    std::istringstream rows(errata);
    for (std::string row; std::getline(rows, row);) {
        if (row.find("| agrees |") == std::string::npos)
            continue;
        ++agreeing;
        const std::string finding = row.substr(row.rfind(" | ", row.size() - 3) + 3);
        // "proven ...: how", or for a claim the paper says does not hold "refuted, as the paper
        // says: how" (Sec. III C's steepness); never a bare "proven".
        // A reference: where it is cited, and what its entry was checked for.
        if (row.find("| reference |") != std::string::npos) {
            BOOST_TEST((finding.rfind("cited at ", 0) == 0 && finding.find("each named once, and its year") != std::string::npos),
                       row);
            continue;
        }
        BOOST_TEST(((finding.find("proven") != std::string::npos || finding.rfind("refuted, as the paper says", 0) == 0) &&
                    finding.find(": ") != std::string::npos),
                   row);
    }
    BOOST_TEST(agreeing > 50u);
    // Eq. 1a prints M v_M + m v_m = M v'_M + m v'_m; derived, m (v_m - v'_m) = -M (v_M - v'_M):
    // the same difference of sides, so one is the other times 1.
    BOOST_TEST(errata_rows_at(errata, "Eq. 1a").at(0).find(
                   "proven equivalent: one equation is the other multiplied by a constant") != std::string::npos);
    // Eq. 14's last member is the derived cosine itself: their difference is 0.
    bool difference = false;
    for (const std::string& row : errata_rows_at(errata, "Eq. 14, line 2"))
        difference = difference ||
                     row.find("proven equal: the difference of the sides simplifies to $0$") != std::string::npos;
    BOOST_TEST(difference);
    // 0 <= cos theta <= 1: inequalities, proven from the signs of factors.
    BOOST_TEST(errata_rows_at(errata, "Sec. III C, after Eq. 14, 4th sentence")
                   .at(0)
                   .find("the sign of each factor of the difference of the sides follows from the domains") !=
               std::string::npos);
    // The same sentence's second half, "the steepness being determined by incident
    // perpendicular velocity": the slope d(theta)/d(eps) at v_perp and at v_perp + delta,
    // said not to be the same, refuted at a point.
    bool steepness = false;
    for (const std::string& row : errata_rows_at(errata, "Sec. III C, after Eq. 14, 4th sentence"))
        steepness = steepness || (row.find("the steepness being determined") != std::string::npos &&
                                  row.find("| agrees |") != std::string::npos &&
                                  row.find("\\frac{\\partial \\theta}{\\partial \\epsilon}") != std::string::npos &&
                                  row.find("refuted, as the paper says") != std::string::npos);
    BOOST_TEST(steepness);
}

BOOST_AUTO_TEST_CASE(appendix_a_line_1_is_reconciled_by_two_edits)
{
    // Typed from the paper: Appendix A's first line prints E'_K = 1/2 m v'_m + 1/2 m v'_M,
    // where 1/2 m v'_m^2 + 1/2 M v'_M^2 belongs: the squares, and M for m in its second term.
    const std::string errata = emit::errata_markdown(library().in_order());
    const std::vector<std::string> rows = errata_rows_at(errata, "Appendix A, line 1");
    BOOST_TEST_REQUIRE(rows.size() == 1u);
    BOOST_TEST(rows[0].find("the squares of $v'_{M,\\parallel}$ and $v'_{m,\\parallel}$ missing, and write $M$ for "
                            "$m$ in") != std::string::npos, rows[0]);
    BOOST_TEST(rows[0].find("no edit") == std::string::npos, rows[0]);
}

BOOST_AUTO_TEST_CASE(eq14_line_1_blames_the_second_factor_of_its_numerator)
{
    // Typed from the paper: Eq. 14's first line puts (1/2 - eps/2) v_1 for v'_2 in the
    // second factor of the numerator of its second member, where the object ball's
    // (1/2 + eps/2) v_1 belongs (its first member has v'_{2,par} there).
    const std::string errata = emit::errata_markdown(library().in_order());
    std::size_t equations = 0;
    for (const std::string& row : errata_rows_at(errata, "Eq. 14, line 1")) {
        if (row.find("| equation |") == std::string::npos || row.find("**disagrees**") == std::string::npos)
            continue;
        ++equations;
        BOOST_TEST(row.find("the second factor of the numerator") != std::string::npos, row);
        BOOST_TEST(row.find("where $v'_{2,\\parallel}$") != std::string::npos, row);
    }
    BOOST_TEST(equations == 1u);
}

BOOST_AUTO_TEST_CASE(eq9_s_lab_components_are_mended_in_the_paper_s_own_variables)
{
    // Typed from the paper: Eq. 9 prints v'_{m,x} as r_x/|r| times the collision-frame
    // v'_{m,par} (with the misprinted sign of eps M (v_{m,par} - v_{M,par})) minus r_y/|r|
    // v_{m,perp}. Beside it the derived column shows the same form mended, in v_par, v_perp and
    // |r|, not Impact's lab-frame form in v_x, v_y and r_x^2 + r_y^2.
    const std::string errata = emit::errata_markdown(library().in_order());
    std::size_t mended = 0;
    for (const std::string& row : errata_rows_at(errata, "Eq. 9")) {
        if (row.find("**disagrees**") == std::string::npos)
            continue;
        ++mended;
        // | where | kind | item | verdict | printed | derived | finding |
        std::vector<std::string> cells;
        for (std::size_t from = 0, at; (at = row.find(" | ", from)) != std::string::npos; from = at + 3)
            cells.push_back(row.substr(from, at - from));
        BOOST_TEST_REQUIRE(cells.size() == 6u, row);
        const std::string& derived = cells[5];
        BOOST_TEST(derived.find("-\\epsilon M (v_{m,\\parallel} - v_{M,\\parallel})") != std::string::npos, derived);
        BOOST_TEST(derived.find("v_{m,\\perp}") != std::string::npos, derived);
        BOOST_TEST(derived.find("\\|r_{mM}\\|") != std::string::npos, derived);
        BOOST_TEST(derived.find("v_{m,x}") == std::string::npos, derived);
        BOOST_TEST(derived.find("r^{2}_{mM,x}") == std::string::npos, derived);
    }
    BOOST_TEST(mended == 1u);
}

BOOST_AUTO_TEST_CASE(a_term_a_finding_names_is_written_as_the_paper_prints_it)
{
    // Typed from the paper: Eq. 9 prints v'_m with + eps M (v_{m,par} - v_{M,par}), whose
    // sign is the misprint; the term is named as printed, not as -eps M (...) nor in
    // another order.
    const std::string errata = emit::errata_markdown(library().in_order());
    const std::vector<std::string> rows = errata_rows_at(errata, "Eq. 9");
    std::size_t named = 0;
    for (const std::string& row : rows)
        named += row.find("the sign of the term $\\epsilon M (v_{m,\\parallel} - v_{M,\\parallel})$") !=
                         std::string::npos
                     ? 1
                     : 0;
    BOOST_TEST(named == 1u);
    // And the report: no term it names starts with a minus.
    const std::string report = read(IMPACT_SOURCE_DIR "/output/report.tex");
    BOOST_TEST(report.find("the sign of the term $-") == std::string::npos);
    BOOST_TEST(report.find("The sign of the term $-") == std::string::npos);
}

// A fictional derivation whose one claim, lim_{x -> infinity} sin(x) = 0, no method settles.
const char* const oscillation = R"toml(id = "oscillating"
title = "An oscillation"

[[symbol]]
name = "x"
dimension = "1"
latex = "x"
domain = "positive"

[[symbol]]
name = "y"
dimension = "1"
latex = "y"

[[step]]
define = "y"
as = "sin(x)"

[[result]]
name = "y"

[[claim]]
name = "dies_away"
paper = "Sec. X"
quote = "The oscillation dies away."
claim = "y = 0"
limit = "x -> infinity"
)toml";

BOOST_AUTO_TEST_CASE(a_limit_no_method_settles_is_undecided_never_disagrees)
{
    // A fictional claim: lim_{x -> infinity} sin(x) = 0. No method (substitution, series,
    // leading term) establishes a limit that does not exist; the claim is not refuted.
    const spec::derivation source = spec::parse_derivation(oscillation, "oscillating.toml");
    const engine::derivation d = engine::derive(source, {});
    BOOST_TEST_REQUIRE(d.paper_checks.size() == 1u);
    BOOST_TEST(emit::comparison_verdict(d.paper_checks[0]) == "undecided");
    const std::string errata = emit::errata_markdown({&d});
    const std::vector<std::string> rows = errata_rows_at(errata, "Sec. X");
    BOOST_TEST_REQUIRE(rows.size() == 1u);
    BOOST_TEST(rows[0].find("**undecided**") != std::string::npos, rows[0]);
    BOOST_TEST(rows[0].find("disagrees") == std::string::npos, rows[0]);
    BOOST_TEST(errata.find("0 agree, 0 disagree, 1 undecided") != std::string::npos);
}


BOOST_AUTO_TEST_CASE(json_and_terminal_list_the_undecided_and_the_not_compared_as_the_errata_does)
{
    // A fictional derivation: a limit no method settles, a claim about experiment, and a
    // line nothing compares. Each is listed in derivations.json and by `impact derive`,
    // undecided or not compared, never as a disagreement.
    const spec::derivation source = spec::parse_derivation(std::string(oscillation) + R"toml(
[[claim]]
name = "springs_tire"
paper = "Sec. Y"
quote = "Real springs tire."
undecided = "a statement about real springs, which experiment decides"

[[not_compared]]
paper = "Footnote 1"
because = "a reference"
)toml", "oscillating.toml");
    const engine::derivation d = engine::derive(source, {});
    const nlohmann::json j = nlohmann::json::parse(emit::derivations_json({&d}));
    const nlohmann::json& checks = j["derivations"][0]["paper_checks"];
    BOOST_TEST_REQUIRE(checks.size() == 2u);
    BOOST_TEST(checks[0]["paper"] == "Sec. X");
    BOOST_TEST(checks[0]["verdict"] == "undecided");
    BOOST_TEST(checks[1]["paper"] == "Sec. Y");
    BOOST_TEST(checks[1]["verdict"] == "undecided");
    BOOST_TEST(checks[1]["printed"] == "Real springs tire.");
    BOOST_TEST(checks[1]["reason"] == "a statement about real springs, which experiment decides");
    const nlohmann::json& uncompared = j["derivations"][0]["not_compared"];
    BOOST_TEST_REQUIRE(uncompared.size() == 1u);
    BOOST_TEST(uncompared[0]["paper"] == "Footnote 1");
    BOOST_TEST(uncompared[0]["because"] == "a reference");

    const std::string text = emit::terminal_text(d);
    BOOST_TEST(text.find("DISAGREES") == std::string::npos, text);
    BOOST_TEST(text.find("Sec. X: dies_away") != std::string::npos, text);
    BOOST_TEST(text.find("Sec. Y: springs_tire (no derivation settles it): undecided") != std::string::npos, text);
    BOOST_TEST(text.find("a statement about real springs, which experiment decides") != std::string::npos, text);
    BOOST_TEST(text.find("Footnote 1: not compared") != std::string::npos, text);
}

BOOST_AUTO_TEST_CASE(derivations_json_gives_each_comparison_the_errata_s_verdict)
{
    // Typed from the paper: Sec. III's first paragraph speaks of experiment (undecided),
    // Eq. 3's second line prints 2m v_M for 2M v_M (disagrees), and no line is left
    // uncompared.
    const nlohmann::json j = nlohmann::json::parse(emit::derivations_json(library().in_order()));
    std::map<std::string, std::set<std::string>> verdicts;
    std::set<std::string> uncompared;
    for (const nlohmann::json& d : j["derivations"]) {
        for (const nlohmann::json& p : d["paper_checks"])
            verdicts[p["paper"].get<std::string>()].insert(p["verdict"].get<std::string>());
        for (const nlohmann::json& line : d["not_compared"])
            uncompared.insert(line["paper"].get<std::string>());
    }
    BOOST_TEST((verdicts["Sec. III, 1st paragraph"] == std::set<std::string>{"undecided"}));
    BOOST_TEST((verdicts["Sec. I, assumptions 1 to 3"] == std::set<std::string>{"undecided"}));
    BOOST_TEST((verdicts["Eq. 3, line 2"] == std::set<std::string>{"disagrees"}));
    BOOST_TEST(uncompared.empty());
    // The references: entry 1 names Brogliato twice, entry 4 (Čepič's) is sound.
    BOOST_TEST((verdicts["Footnote 1"] == std::set<std::string>{"disagrees"}));
    BOOST_TEST((verdicts["Footnote 4"] == std::set<std::string>{"agrees"}));
    // Every line the list says is compared has a verdict in the JSON.
    for (const printed_line& line : paper)
        if (!line.not_compared)
            BOOST_TEST(verdicts.count(line.where) == 1u, line.where << " has no verdict in derivations.json");
}
