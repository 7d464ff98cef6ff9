// Compatibility path: the header lives in the geometry stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_CURVE_PROBLEM_GENERATOR_H
#define BEZOUTIAN_FORWARD_CURVE_PROBLEM_GENERATOR_H
#include <bezoutian/geometry/Curve_problem_generator.h>
#endif
