// The batch kernels instantiated in double, accurate and fast (impact::fast), for
// tests/vectorised.cmake to compile and read the compiler's report of which loops it vectorised.
#include "impact/impact.hpp"

template void impact::collide_batch<double>(const impact::collide_batch_data<double, 2>&);
template void impact::collide_batch<double>(const impact::collide_batch_data<double, 3>&);
template void impact::collide_wall_batch<double>(const impact::collide_wall_batch_data<double, 2>&);
template void impact::collide_wall_batch<double>(const impact::collide_wall_batch_data<double, 3>&);
template void impact::collide_rough_batch<double>(const impact::collide_rough_batch_data<double, 2>&);
template void impact::collide_rough_batch<double>(const impact::collide_rough_batch_data<double, 3>&);
template void impact::collide_batch<double>(const impact::collide_batch_data<double, 2>&, impact::fast_t);
template void impact::collide_batch<double>(const impact::collide_batch_data<double, 3>&, impact::fast_t);
template void impact::collide_wall_batch<double>(const impact::collide_wall_batch_data<double, 2>&, impact::fast_t);
template void impact::collide_wall_batch<double>(const impact::collide_wall_batch_data<double, 3>&, impact::fast_t);
template void impact::collide_rough_batch<double>(const impact::collide_rough_batch_data<double, 2>&, impact::fast_t);
template void impact::collide_rough_batch<double>(const impact::collide_rough_batch_data<double, 3>&, impact::fast_t);
template void impact::collide_wall_rough_batch<double>(const impact::collide_wall_rough_batch_data<double, 2>&);
template void impact::collide_wall_rough_batch<double>(const impact::collide_wall_rough_batch_data<double, 2>&, impact::fast_t);
template void impact::collide_wall_rough_batch<double>(const impact::collide_wall_rough_batch_data<double, 3>&);
template void impact::collide_wall_rough_batch<double>(const impact::collide_wall_rough_batch_data<double, 3>&, impact::fast_t);
template void impact::collide_line_batch<double>(const impact::collide_line_batch_data<double, 0>&);
template void impact::collide_line_batch<double>(const impact::collide_line_batch_data<double, 0>&, impact::fast_t);
