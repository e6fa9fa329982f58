// Prints sums, products and a factorisation in GiNaC's own order of terms (not Impact's),
// for the test ginac_order_is_the_same_on_every_run (tests/same_every_run.cmake), which runs
// it several times: linked as Impact is (CMakeLists.txt, impact_ginac), the order must not
// change from run to run.
#include <ginac/ginac.h>

#include <iostream>

int main()
{
    using namespace GiNaC;
    const symbol M("M"), m("m"), v("v"), w("w"), eps("eps");
    const ex sum = sin(v) + pow(v, 2) * w + sqrt(m) + M * m * v + exp(w) + abs(v) + 3 * pow(w, 3) + atan2(v, w);
    const ex product = sin(v) * pow(M + m, 2) * sqrt(m) * exp(w) * abs(v - w) * (1 + eps);
    std::cout << sum << "\n" << product << "\n"
              << factor(expand(pow(M + m, 2) * (v - w) * (1 - pow(eps, 2)))) << "\n"
              << normal((M * v + m * w) / (M + m) - v) << "\n";
}
