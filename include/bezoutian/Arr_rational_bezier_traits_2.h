// Compatibility path: the header lives in the arrangement stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_ARR_RATIONAL_BEZIER_TRAITS_2_H
#define BEZOUTIAN_FORWARD_ARR_RATIONAL_BEZIER_TRAITS_2_H
#include <bezoutian/arrangement/Arr_rational_bezier_traits_2.h>
#endif
