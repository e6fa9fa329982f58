// Uses every kernel of Impact's public API through the installed package, and checks
// each against a physics law; exits non-zero when one does not hold.
#include <impact/impact.hpp>

#include <array>
#include <cmath>
#include <cstddef>
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

    // A batch in its own arrays gives each pair the scalar kernel's result: the 2D pair above
    // lifted to 3D, and the separating 3D pair.
    const std::array<double, 3> E_M{1, 1, 0}, E_m{0, 0, 0}, u_M{-1, -0.5, 0}, u_m{0.5, 0, 0};
    const auto lifted = impact::collide(3.0, 1.0, E_M, E_m, u_M, u_m, 0.5);
    impact::collide_batch_arrays<double, 3> batch(2);
    batch.M()[0] = 3.0;
    batch.m()[0] = 1.0;
    batch.eps()[0] = 0.5;
    batch.M()[1] = batch.m()[1] = batch.eps()[1] = 1.0;
    for (std::size_t d = 0; d < 3; ++d) {
        batch.C_M(d)[0] = E_M[d];
        batch.C_m(d)[0] = E_m[d];
        batch.v_M(d)[0] = u_M[d];
        batch.v_m(d)[0] = u_m[d];
        batch.C_M(d)[1] = D_M[d];
        batch.C_m(d)[1] = D_m[d];
        batch.v_M(d)[1] = w_M[d];
        batch.v_m(d)[1] = w_m[d];
    }
    impact::collide_batch(batch.data());
    expect(batch.status()[0] == impact::status::ok && batch.status()[1] == impact::status::separating,
           "the statuses of a batch");
    for (std::size_t d = 0; d < 3; ++d) {
        expect(batch.v_M(d)[0] == lifted.v_M[d] && batch.v_m(d)[0] == lifted.v_m[d], "a batch's velocities");
        expect(batch.v_M(d)[1] == w_M[d] && batch.v_m(d)[1] == w_m[d], "a separating pair in a batch is left alone");
        expect(std::abs(lifted.v_M[d] - (d < 2 ? plane.v_M[d] : 0.0)) < 1e-14, "a 2D collision lifted to 3D");
    }
    return failures == 0 ? 0 : 1;
}
