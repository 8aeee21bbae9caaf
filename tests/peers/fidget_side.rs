//! The fidget side: the same models written with fidget's tree API, as a VM shape and as a JIT
//! shape, meshed by fidget's octree (manifold dual contouring) over its default `[-1, 1]³`
//! region at depth `log2 n` (256³ = depth 8).

use fidget::context::Tree;
use fidget::jit::JitShape;
use fidget::mesh::{Mesh, Octree, Settings};
use fidget::render::ThreadPool;
use fidget::shape::{BoundShape, Shape};
use fidget::vm::VmShape;
use glam::DVec3;
use solidkit_kernel::IndexedMesh;

/// `None` for one thread (fidget then meshes on the calling thread), else a pool of N.
pub struct Pool(Option<ThreadPool>);

impl Pool {
    /// The pool for `threads` threads.
    pub fn new(threads: usize) -> Self {
        Self((threads > 1).then(|| {
            ThreadPool::Custom(
                rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .expect("thread pool"),
            )
        }))
    }
}

/// `sqrt(x² + y² + z²) − 0.6`.
fn sphere() -> Tree {
    (Tree::x().square() + Tree::y().square() + Tree::z().square()).sqrt() - 0.6
}

/// With `(X, Y, Z) = 30 (x, y, z)` and `g = sin X cos Y + sin Y cos Z + sin Z cos X`:
/// `max(|(X, Y, Z)| − 25, |g| − 0.2)`.
fn gyroid_sphere() -> Tree {
    let (x, y, z) = (Tree::x() * 30.0, Tree::y() * 30.0, Tree::z() * 30.0);
    let g = x.sin() * y.cos() + y.sin() * z.cos() + z.sin() * x.cos();
    let ball = (x.square() + y.square() + z.square()).sqrt() - 25.0;
    ball.max(g.abs() - 0.2)
}

fn tree(name: &str) -> Tree {
    match name {
        "sphere" => sphere(),
        "gyroid-sphere" => gyroid_sphere(),
        other => panic!("no fidget tree for '{other}'"),
    }
}

enum Compiled {
    Vm(BoundShape<'static, fidget::vm::VmFunction, f32>),
    Jit(BoundShape<'static, fidget::jit::JitFunction, f32>),
}

/// A model compiled for fidget, ready to mesh.
pub struct Case {
    shape: Compiled,
    depth: u8,
}

fn depth(n: usize) -> u8 {
    assert!(
        n.is_power_of_two(),
        "fidget's octree needs a power-of-two grid"
    );
    n.trailing_zeros() as u8
}

impl Case {
    /// The model for fidget's bytecode interpreter.
    pub fn vm(name: &str, n: usize) -> Self {
        let shape: Shape<_> = VmShape::from(tree(name));
        Self {
            shape: Compiled::Vm(shape.try_into().expect("no free variables")),
            depth: depth(n),
        }
    }

    /// The model compiled to native code.
    pub fn jit(name: &str, n: usize) -> Self {
        let shape: Shape<_> = JitShape::from(tree(name));
        Self {
            shape: Compiled::Jit(shape.try_into().expect("no free variables")),
            depth: depth(n),
        }
    }

    /// Builds the octree and walks it into a mesh (fidget's own mesh type: what is timed).
    pub fn mesh(&self, pool: &Pool) -> Mesh {
        let settings = Settings {
            depth: self.depth,
            threads: pool.0.as_ref(),
            ..Default::default()
        };
        match &self.shape {
            Compiled::Vm(s) => Octree::build(s, &settings)
                .expect("not cancelled")
                .walk_dual(),
            Compiled::Jit(s) => Octree::build(s, &settings)
                .expect("not cancelled")
                .walk_dual(),
        }
    }
}

/// A fidget mesh as a solidkit mesh (for the topology check; not timed).
pub fn to_indexed(mesh: &Mesh) -> IndexedMesh {
    IndexedMesh::new(
        mesh.vertices
            .iter()
            .map(|v| DVec3::new(v.x as f64, v.y as f64, v.z as f64))
            .collect(),
        mesh.triangles
            .iter()
            .map(|t| [t.x as u32, t.y as u32, t.z as u32])
            .collect(),
    )
}
