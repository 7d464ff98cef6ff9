// Compatibility path: the header lives in the intersection stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_CURVE_SURFACE_INTERSECTION_H
#define BEZOUTIAN_FORWARD_CURVE_SURFACE_INTERSECTION_H
#include <bezoutian/intersection/Curve_surface_intersection.h>
#endif
