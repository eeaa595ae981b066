// Deliberately unguarded include cycle (b -> a -> b) for the include-cycle test.
#include "ffx_dof_test_cycle_a.h"
