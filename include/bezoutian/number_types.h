// Compatibility path: the header lives in the arithmetic stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_NUMBER_TYPES_H
#define BEZOUTIAN_FORWARD_NUMBER_TYPES_H
#include <bezoutian/arithmetic/number_types.h>
#endif
