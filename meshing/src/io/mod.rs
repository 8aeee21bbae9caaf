//! Mesh file input and output (placeholder until the I/O module lands).
