//! The one bound on worker threads shared by every front end and crate that
//! starts threads (`--threads`, Python's `threads=`, kick-flight's
//! `flight_many`): at most [`THREADS_PER_CORE`] per available core, never
//! above [`MAX_THREADS`].

/// Most worker threads on any machine.
pub const MAX_THREADS: usize = 1024;
/// Threads per available core allowed (more only adds switching).
pub const THREADS_PER_CORE: usize = 4;

/// Cores this process may use (1 if unknown).
pub fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// Most threads allowed here: [`THREADS_PER_CORE`] per core, at most [`MAX_THREADS`].
pub fn max_threads() -> usize {
    (THREADS_PER_CORE * cores()).clamp(1, MAX_THREADS)
}
