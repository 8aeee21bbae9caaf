//! Tests of the simplification pass.
