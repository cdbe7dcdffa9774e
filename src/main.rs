//! `ladder`: thin entry point. Parses arguments, runs the library, maps
//! errors to exit codes (2 bad input, 1 failed run).

fn main() {
    std::process::exit(jacobs_ladder::cli::main_with_args(std::env::args_os()));
}
