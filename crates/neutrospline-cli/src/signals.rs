//! Interruption: SIGINT (Ctrl-C) and SIGTERM set a flag instead of killing the process, so that
//! a long `eval -o FILE` stops between two rows, removes its temporary file and leaves the old
//! output untouched. The process then exits with the conventional status 128 + signal number
//! (130 for SIGINT, 143 for SIGTERM).

use std::fmt;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, OnceLock};

/// The signal received, 0 if none (set by the handlers, which only store a number).
static RECEIVED: OnceLock<Arc<AtomicUsize>> = OnceLock::new();

/// Installs the handlers for SIGINT and SIGTERM (once, at start-up). A failure leaves the
/// default behaviour: the process is killed (and its temporary file may remain).
pub fn install() {
    let flag = RECEIVED.get_or_init(|| Arc::new(AtomicUsize::new(0)));
    for signal in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        let number = usize::try_from(signal).unwrap_or(0);
        let _ = signal_hook::flag::register_usize(signal, Arc::clone(flag), number);
    }
}

/// The signal received since [`install`], if any.
pub fn received() -> Option<i32> {
    let seen = RECEIVED.get()?.load(Ordering::Relaxed);
    (seen != 0).then(|| i32::try_from(seen).ok()).flatten()
}

/// Fails with [`Interrupted`] once a signal has been received.
///
/// # Errors
/// [`Interrupted`].
pub fn check() -> Result<(), Interrupted> {
    match received() {
        Some(signal) => Err(Interrupted(signal)),
        None => Ok(()),
    }
}

/// The work was stopped by a signal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Interrupted(pub i32);

impl Interrupted {
    /// The exit status: 128 + the signal number.
    pub fn exit_code(self) -> u8 {
        u8::try_from(128 + self.0).unwrap_or(255)
    }
}

impl fmt::Display for Interrupted {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = match self.0 {
            signal_hook::consts::SIGINT => "SIGINT",
            signal_hook::consts::SIGTERM => "SIGTERM",
            _ => "a signal",
        };
        write!(f, "interrupted by {name}")
    }
}

impl std::error::Error for Interrupted {}
