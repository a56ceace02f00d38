//! The `moving-hertz` command-line tool. Run `moving-hertz help` for the commands.

mod cli;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match cli::run(&args) {
        Ok(()) => {}
        Err(msg) => {
            eprintln!("moving-hertz: {msg}");
            std::process::exit(2);
        }
    }
}
