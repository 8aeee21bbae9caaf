//! Rhai scripts (`.rhai`) as a front end: every primitive, operation and transform of the kernel as
//! functions and methods, run in a sandbox (no `import` or `eval`, limits on operations, call
//! depth, expression depth, sizes, wall-clock time and tree size).
//!
//! The script's value is the solid passed to its last `export(solid)` call, or else the value of
//! its last expression. What the script prints (`print`, `debug`) goes to the
//! [`ScriptOptions::print`] sink, or nowhere: the library never writes to standard output or
//! standard error itself.

mod api;
mod curve;
mod defines;
mod error;
mod node;
mod shape;
mod swept;
#[cfg(test)]
mod tests;

pub use error::ScriptError;
use shape::Shape;

use ::rhai::packages::{Package, StandardPackage};
use ::rhai::{Dynamic, Engine};
use solidkit_kernel::Solid;
use solidkit_kernel::json::MeshResolver;
use std::cell::Cell;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// The limits of the sandbox.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Limits {
    /// Most operations (Rhai's count of evaluation steps) a script may take.
    pub max_operations: u64,
    /// Wall-clock time a script may run.
    pub max_time: Duration,
    /// Deepest nesting of function calls.
    pub max_call_levels: usize,
    /// Deepest nesting of expressions (at top level and in functions).
    pub max_expr_depth: usize,
    /// Longest string, in bytes.
    pub max_string_size: usize,
    /// Most elements of an array.
    pub max_array_size: usize,
    /// Most entries of a map.
    pub max_map_size: usize,
    /// Most nodes of a solid built by the script (a shared subtree counts once per use).
    pub max_nodes: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_operations: 20_000_000,
            max_time: Duration::from_millis(1500),
            max_call_levels: 64,
            max_expr_depth: 64,
            max_string_size: 1 << 20,
            max_array_size: 100_000,
            max_map_size: 10_000,
            max_nodes: 1_000_000,
        }
    }
}

thread_local! {
    /// The wall-clock deadline of the script running on this thread, and its time limit.
    static DEADLINE: Cell<Option<(Instant, Duration)>> = const { Cell::new(None) };
}

/// Fails once the deadline of the script running on this thread has passed. Every constructor of
/// the API calls it: `on_progress` looks at the clock only every 1024 Rhai operations, and a script
/// can spend its time in few operations inside solidkit's own functions.
pub(super) fn check_deadline() -> shape::Fallible<()> {
    match DEADLINE.get() {
        Some((deadline, limit)) if Instant::now() > deadline => shape::fail(format!(
            "the script ran longer than the {} s time limit",
            limit.as_secs_f64()
        )),
        _ => Ok(()),
    }
}

/// Stack of the thread that runs a script: deep (but limited) Rhai recursion must not overflow.
const STACK_SIZE: usize = 64 << 20;

/// Where the lines a script prints go: `print(x)` passes the text of `x`, `debug(x)` passes the
/// place of the call as Rhai writes it (`LINE:COLUMN`), `: ` and the debug text of `x`.
/// The text is the script's own and may hold any character (newlines, escape sequences): a sink
/// that writes to a terminal should escape it.
pub type PrintSink = Arc<dyn Fn(&str) + Send + Sync>;

/// How a script runs: the sandbox's limits and where its output goes.
#[derive(Clone, Default)]
#[non_exhaustive]
pub struct ScriptOptions {
    /// The limits of the sandbox.
    pub limits: Limits,
    /// Receives each line printed by `print` and `debug`; `None` discards them.
    pub print: Option<PrintSink>,
    /// `NAME=VALUE` definitions (the CLI's `-D`): each `NAME` is a constant in the script's scope
    /// before it runs, `VALUE` a Rhai literal (number, string, boolean, array, object map).
    pub defines: Vec<String>,
}

impl std::fmt::Debug for ScriptOptions {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ScriptOptions")
            .field("limits", &self.limits)
            .field("print", &self.print.as_ref().map(|_| "Fn(&str)"))
            .field("defines", &self.defines)
            .finish()
    }
}

/// Runs the script `source` (named `file` in errors) with the default [`Limits`], its printed
/// output discarded; `mesh` nodes load their files through `resolver`.
pub fn eval(
    source: &str,
    file: &str,
    resolver: Arc<dyn MeshResolver + Send + Sync>,
) -> Result<Solid, ScriptError> {
    eval_with_options(source, file, resolver, &ScriptOptions::default())
}

/// Runs the script `source` like [`eval`], with the given limits.
pub fn eval_with(
    source: &str,
    file: &str,
    resolver: Arc<dyn MeshResolver + Send + Sync>,
    limits: Limits,
) -> Result<Solid, ScriptError> {
    let options = ScriptOptions {
        limits,
        ..ScriptOptions::default()
    };
    eval_with_options(source, file, resolver, &options)
}

/// Runs the script `source` like [`eval`], with the given limits and print sink.
pub fn eval_with_options(
    source: &str,
    file: &str,
    resolver: Arc<dyn MeshResolver + Send + Sync>,
    options: &ScriptOptions,
) -> Result<Solid, ScriptError> {
    std::thread::scope(|s| {
        std::thread::Builder::new()
            .name("rhai".into())
            .stack_size(STACK_SIZE)
            .spawn_scoped(s, || run(source, file, resolver, options))
            .map_err(|e| ScriptError::plain(file, format!("cannot start the script thread: {e}")))?
            .join()
            .unwrap_or_else(|_| Err(ScriptError::plain(file, "the script runner panicked")))
    })
}

fn run(
    source: &str,
    file: &str,
    resolver: Arc<dyn MeshResolver + Send + Sync>,
    options: &ScriptOptions,
) -> Result<Solid, ScriptError> {
    let limits = options.limits;
    let exported = Arc::new(Mutex::new(None::<Shape>));
    let mut scope = defines::scope(&options.defines, file, &limits)?;
    DEADLINE.set(Some((Instant::now() + limits.max_time, limits.max_time)));
    let engine = engine(&limits, options.print.clone(), resolver, exported.clone());
    let ast = engine
        .compile(source)
        .map_err(|e| error::from_parse(source, file, &e, &limits))?;
    let value: Dynamic = engine
        .eval_ast_with_scope(&mut scope, &ast)
        .map_err(|e| error::from_eval(source, file, &e, &limits))?;
    let last = exported.lock().ok().and_then(|mut e| e.take());
    match last {
        Some(shape) => Ok(shape.solid),
        None => match value.try_cast::<Shape>() {
            Some(shape) => Ok(shape.solid),
            None => Err(ScriptError::plain(
                file,
                "the script made no solid: end it with a solid expression or call export(solid)",
            )),
        },
    }
}

/// The sandboxed engine: standard packages, our API, no `eval`, no modules, all limits set; no
/// `sleep` (it ignored the deadline) and no `curry` (a curried function pointer holds deep copies of
/// its arguments, outside Rhai's size limits: `f = f.curry(f)` doubles memory per step).
fn engine(
    limits: &Limits,
    print: Option<PrintSink>,
    resolver: Arc<dyn MeshResolver + Send + Sync>,
    exported: Arc<Mutex<Option<Shape>>>,
) -> Engine {
    let mut engine = Engine::new_raw();
    engine.register_global_module(StandardPackage::new().as_shared_module());
    engine.disable_symbol("eval");
    engine.disable_symbol("curry");
    // Functions registered on the engine are found before the standard package's.
    engine.register_fn("sleep", |_: rhai::INT| -> shape::Fallible<()> {
        no_sleep()
    });
    engine.register_fn("sleep", |_: rhai::FLOAT| -> shape::Fallible<()> {
        no_sleep()
    });
    engine.set_max_operations(limits.max_operations);
    engine.set_max_call_levels(limits.max_call_levels);
    engine.set_max_expr_depths(limits.max_expr_depth, limits.max_expr_depth);
    engine.set_max_string_size(limits.max_string_size);
    engine.set_max_array_size(limits.max_array_size);
    engine.set_max_map_size(limits.max_map_size);
    let start = Instant::now();
    let max_time = limits.max_time;
    engine.on_progress(move |ops| {
        (ops % 1024 == 0 && start.elapsed() > max_time).then(|| Dynamic::from(error::TIMEOUT))
    });
    // Rhai's default hooks write to standard output: replaced even without a sink.
    match print {
        Some(sink) => {
            let debug_sink = sink.clone();
            engine.on_print(move |s| sink(s));
            engine.on_debug(move |s, _, pos| debug_sink(&format!("{pos:?}: {s}")));
        }
        None => {
            engine.on_print(|_| {});
            engine.on_debug(|_, _, _| {});
        }
    }
    api::register(&mut engine, limits.max_nodes, resolver, exported);
    curve::register(&mut engine);
    swept::register(&mut engine, limits.max_nodes);
    engine
}

fn no_sleep() -> shape::Fallible<()> {
    shape::fail("'sleep' is not available in solidkit scripts")
}
