//! The `moving-hertz` command-line tool. Run `moving-hertz --help` for the commands.

mod cli;
mod studies;

fn main() {
    std::process::exit(cli::main());
}
