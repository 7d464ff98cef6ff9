// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_SURFACE_BEZOUTIAN_MATRICES_H
#define BEZOUTIAN_FORWARD_SURFACE_BEZOUTIAN_MATRICES_H
#include <bezoutian/elimination/Surface_bezoutian_matrices.h>
#endif
