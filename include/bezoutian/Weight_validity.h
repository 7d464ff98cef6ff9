// Compatibility path: the header lives in the geometry stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_WEIGHT_VALIDITY_H
#define BEZOUTIAN_FORWARD_WEIGHT_VALIDITY_H
#include <bezoutian/geometry/Weight_validity.h>
#endif
