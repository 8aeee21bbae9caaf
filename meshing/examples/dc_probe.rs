//! Temporary probe.
use solidkit_kernel::models::Model;
use solidkit_meshing::TopologyReport;
use solidkit_meshing::dual_contouring::{DcOptions, mesh_dc};
use solidkit_meshing::marching_cubes::GridSpec;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let model = Model::by_name(&args[1]).unwrap();
    let n: usize = args[2].parse().unwrap();
    let tol: Option<f64> = args.get(3).map(|t| t.parse().unwrap());
    let spec = GridSpec::covering(&model.domain, n).unwrap();
    let p = model.solid.compile();
    let t = std::time::Instant::now();
    let (m, st) = mesh_dc(&p, spec, &DcOptions { tolerance: None, ..Default::default() }).unwrap();
    let t1 = t.elapsed().as_secs_f64();
    let r = TopologyReport::of(&m);
    println!("plain: {t1:.3}s tris {} closed {} manifold {} genus {:?} cell {} stats {:?}", r.faces, r.closed, r.manifold, r.genus, spec.cell, st);
    if let Some(tol) = tol {
        let t = std::time::Instant::now();
        let (m2, _) = mesh_dc(&p, spec, &DcOptions { tolerance: Some(tol), ..Default::default() }).unwrap();
        let t2 = t.elapsed().as_secs_f64();
        let r2 = TopologyReport::of(&m2);
        println!("tol {tol}: {t2:.3}s tris {} closed {} manifold {} genus {:?} ratio {:.1}", r2.faces, r2.closed, r2.manifold, r2.genus, r.faces as f64 / r2.faces as f64);
    }
}
