// Compatibility path: the header lives in the topology stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_CURVE_TOPOLOGY_BY_SUBDIVISION_H
#define BEZOUTIAN_FORWARD_CURVE_TOPOLOGY_BY_SUBDIVISION_H
#include <bezoutian/topology/Curve_topology_by_subdivision.h>
#endif
