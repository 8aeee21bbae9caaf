//! Merging brick outputs into one mesh numbered exactly as the dense path numbers it: vertices by
//! grid edge key (duplicates from shared brick faces removed), triangles by cell and case order.

use super::brick::BrickOutput;
use crate::sink::MeshSink;
use rayon::prelude::*;

pub(crate) fn assemble(outputs: Vec<BrickOutput>, sink: &mut impl MeshSink) {
    let mut edges: Vec<(u64, glam::DVec3)> =
        Vec::with_capacity(outputs.iter().map(|o| o.edges.len()).sum());
    let mut triangles: Vec<(u64, [u64; 3])> =
        Vec::with_capacity(outputs.iter().map(|o| o.triangles.len()).sum());
    for o in outputs {
        edges.extend(o.edges);
        triangles.extend(o.triangles);
    }
    edges.par_sort_unstable_by_key(|e| e.0);
    edges.dedup_by_key(|e| e.0);
    triangles.par_sort_unstable_by_key(|t| t.0);
    sink.reserve(edges.len(), triangles.len());
    let ids: Vec<u32> = edges.iter().map(|e| sink.add_vertex(e.1)).collect();
    let index = |key: u64| {
        let at = edges
            .binary_search_by_key(&key, |e| e.0)
            .expect("every triangle corner is a crossing edge");
        ids[at]
    };
    let resolved: Vec<[u32; 3]> = triangles.par_iter().map(|t| t.1.map(index)).collect();
    for t in resolved {
        sink.add_triangle(t);
    }
}
