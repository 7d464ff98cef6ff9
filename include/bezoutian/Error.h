// Compatibility path: the header lives in the arithmetic stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_ERROR_H
#define BEZOUTIAN_FORWARD_ERROR_H
#include <bezoutian/arithmetic/Error.h>
#endif
