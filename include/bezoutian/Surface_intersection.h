// Compatibility path: the header lives in the intersection stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_SURFACE_INTERSECTION_H
#define BEZOUTIAN_FORWARD_SURFACE_INTERSECTION_H
#include <bezoutian/intersection/Surface_intersection.h>
#endif
