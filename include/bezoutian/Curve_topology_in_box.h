// Compatibility path: the header lives in the topology stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_CURVE_TOPOLOGY_IN_BOX_H
#define BEZOUTIAN_FORWARD_CURVE_TOPOLOGY_IN_BOX_H
#include <bezoutian/topology/Cgal_curve_analysis.h>
#endif
