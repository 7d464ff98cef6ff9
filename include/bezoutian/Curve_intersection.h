// Compatibility path: the header lives in the intersection stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_CURVE_INTERSECTION_H
#define BEZOUTIAN_FORWARD_CURVE_INTERSECTION_H
#include <bezoutian/intersection/Curve_intersection.h>
#endif
