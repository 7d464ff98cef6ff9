// Compatibility path: the header lives in the geometry stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_DEGENERACY_H
#define BEZOUTIAN_FORWARD_DEGENERACY_H
#include <bezoutian/geometry/Degeneracy.h>
#endif
