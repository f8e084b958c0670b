//! The `neutrospline` command; everything is in the library crate `neutrospline_cli`.

fn main() -> std::process::ExitCode {
    neutrospline_cli::main_with_args()
}
