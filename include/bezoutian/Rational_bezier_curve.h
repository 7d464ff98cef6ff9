// Compatibility path: the header lives in the geometry stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_RATIONAL_BEZIER_CURVE_H
#define BEZOUTIAN_FORWARD_RATIONAL_BEZIER_CURVE_H
#include <bezoutian/geometry/Rational_bezier_curve.h>
#endif
