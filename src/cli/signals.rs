//! SIGINT (Ctrl-C), SIGTERM (`kill`, `timeout`, Slurm) and SIGHUP (a closed terminal):
//! the program stops, removes what it had not finished, and says so.

use super::files::registry;
use std::io;
use std::sync::Mutex;

/// What the program is doing, for the message a signal prints.
static ACTIVITY: Mutex<String> = Mutex::new(String::new());

/// Says what the program is doing now (`rendering scenes/x.toml into x.png`), for the
/// message printed if a signal stops it.
pub fn set_activity(what: impl Into<String>) {
    *ACTIVITY.lock().unwrap_or_else(std::sync::PoisonError::into_inner) = what.into();
}

/// Installs a handler for SIGINT, SIGTERM and SIGHUP. On the first of them it removes
/// every temporary file and still-empty created folder ([`super::remove_temporary_files`]),
/// prints on stderr `PROGRAM: stopped by SIGTERM while <activity>`, what it removed and that
/// nothing was left behind, and exits with 128 + the signal's number (130, 143, 129), the
/// shell's codes for a program a signal ended.
///
/// The handler keeps the registry locked until the process has exited, so no write can
/// create a new temporary file or finish a rename after the cleanup. On systems other
/// than Unix this installs nothing.
///
/// # Errors
/// If the system refuses the handler, or its thread cannot start.
pub fn clean_up_on_signals(program: &'static str) -> io::Result<()> {
    super::files::track();
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])?;
        std::thread::Builder::new()
            .name("signals".into())
            .spawn(move || {
                if let Some(signal) = signals.forever().next() {
                    stop(program, signal);
                }
            })?;
    }
    #[cfg(not(unix))]
    let _ = program;
    Ok(())
}

/// Cleans up, says so and exits: never returns.
#[cfg(unix)]
fn stop(program: &str, signal: i32) {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    use std::io::Write as _;
    let name = match signal {
        SIGINT => "SIGINT (Ctrl-C)",
        SIGTERM => "SIGTERM",
        SIGHUP => "SIGHUP",
        _ => "a signal",
    };
    let activity = ACTIVITY
        .lock()
        .map_or_else(|e| e.into_inner().clone(), |a| a.clone());
    let mut registry = registry();
    let removed = registry.clean();
    let removed: String = removed
        .iter()
        .map(|p| format!("; removed the unfinished temporary file {}", p.display()))
        .collect();
    let activity = if activity.is_empty() {
        String::new()
    } else {
        format!(" while {activity}")
    };
    // A progress bar may hold the line: start a new one. A closed stderr must not keep
    // the process from exiting (eprintln! would panic this thread instead).
    let _ = writeln!(
        io::stderr(),
        "\n{program}: stopped by {name}{activity}{removed}; nothing was left behind"
    );
    std::process::exit(128 + signal);
}
