// Uses every kernel of Impact's public API through the installed package, and checks
// each against a physics law; exits non-zero when one does not hold.
#include <impact/impact.hpp>

#include <array>
#include <cmath>
#include <cstdio>

namespace {

int failures = 0;

void expect(bool ok, const char* what)
{
    if (!ok) {
        std::printf("consumer: %s does not hold\n", what);
        ++failures;
    }
}

} // namespace

int main()
{
    // Equal masses, elastic, head-on: the velocities are exchanged.
    const auto line = impact::collide_line(1.0, 1.0, 2.0, -1.0, 1.0);
    expect(line.v_M == -1.0 && line.v_m == 2.0, "exchange of velocities along the line");

    // Kinetic energy lost: (1 - eps^2) of the energy of the relative motion, 1/2 mu dv^2.
    expect(std::abs(impact::energy_loss(2.0, 2.0, 1.0, -1.0, 0.0) + 2.0) < 1e-15, "energy lost at eps = 0");

    // An elastic billiard collision scatters at a right angle.
    expect(std::abs(impact::scatter_angle(1.0f, 0.5f, 1.0f) - std::acos(0.0f)) < 1e-6f, "right-angle scattering");

    // In 2D and 3D, momentum is conserved and a separating pair is left alone.
    const std::array<double, 2> C_M{1, 1}, C_m{0, 0}, v_M{-1, -0.5}, v_m{0.5, 0};
    const auto plane = impact::collide(3.0, 1.0, C_M, C_m, v_M, v_m, 0.5);
    expect(plane.status == impact::status::ok, "a 2D collision is resolved");
    for (int i = 0; i < 2; ++i)
        expect(std::abs(3 * plane.v_M[i] + plane.v_m[i] - (3 * v_M[i] + v_m[i])) < 1e-14, "2D momentum");
    const std::array<double, 3> D_M{0, 0, 2}, D_m{0, 0, 0}, w_M{0, 0, 1}, w_m{0, 0, 0};
    const auto space = impact::collide(1.0, 1.0, D_M, D_m, w_M, w_m, 1.0);
    expect(space.status == impact::status::separating && space.v_M == w_M, "a separating 3D pair is left alone");
    return failures == 0 ? 0 : 1;
}
