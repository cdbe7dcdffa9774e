//! `ladder`: thin entry point. Starts the thread pool (with fewer threads
//! when the machine refuses some), parses arguments, runs the library,
//! maps errors to exit codes (2 bad input, 1 failed run).

use rayon::{ThreadPool, ThreadPoolBuilder};

fn main() {
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    let run = || jacobs_ladder::cli::main_with_args(args.clone());
    let code = match ThreadPoolBuilder::new().build_global() {
        Ok(()) => run(),
        // Threads refused (a process limit, a container's pids limit): the
        // global pool cannot be built again, so a pool of our own, as large
        // as the machine allows, runs the command.
        Err(e) => match fallback_pool() {
            Some(pool) => {
                eprintln!(
                    "ladder: note: could not start the usual threads ({e}); running with {}",
                    match pool.current_num_threads() {
                        1 => "one thread".to_string(),
                        n => format!("{n} threads"),
                    }
                );
                pool.install(run)
            }
            None => {
                eprintln!(
                    "ladder: cannot start a thread ({e}): the limit on processes (ulimit -u) or \
                     the container's pids limit is reached; raise it or stop other processes"
                );
                1
            }
        },
    };
    std::process::exit(code);
}

/// The largest pool the machine allows, halving from the number of cores;
/// at the least this thread alone.
fn fallback_pool() -> Option<ThreadPool> {
    let mut n = std::thread::available_parallelism().map_or(1, |n| n.get());
    while n > 1 {
        n /= 2;
        // The command runs on a worker: give it a main thread's stack.
        let builder = ThreadPoolBuilder::new().num_threads(n).stack_size(8 << 20);
        if let Ok(pool) = builder.build() {
            return Some(pool);
        }
    }
    ThreadPoolBuilder::new()
        .num_threads(1)
        .use_current_thread()
        .build()
        .ok()
}
