Include "include_cycle_b.inc";
