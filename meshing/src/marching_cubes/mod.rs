//! Marching cubes (placeholder until the module lands).
