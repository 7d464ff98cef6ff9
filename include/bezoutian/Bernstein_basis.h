// Compatibility path: the header lives in the geometry stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_BERNSTEIN_BASIS_H
#define BEZOUTIAN_FORWARD_BERNSTEIN_BASIS_H
#include <bezoutian/geometry/Bernstein_basis.h>
#endif
