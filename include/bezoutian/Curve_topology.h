// Compatibility path: the header lives in the topology stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_CURVE_TOPOLOGY_H
#define BEZOUTIAN_FORWARD_CURVE_TOPOLOGY_H
#include <bezoutian/topology/Curve_topology.h>
#endif
