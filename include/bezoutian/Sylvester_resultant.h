// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_SYLVESTER_RESULTANT_H
#define BEZOUTIAN_FORWARD_SYLVESTER_RESULTANT_H
#include <bezoutian/elimination/Sylvester_resultant.h>
#endif
