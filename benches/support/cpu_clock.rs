//! The clock the peer benchmarks share with `bench/pinocchio/peers.cpp`: this thread's CPU
//! time, so that time the thread is descheduled on a shared machine is left out; and the
//! median of the rounds.

#[cfg(not(target_os = "linux"))]
use std::time::Instant;

/// This thread's CPU time in ns (`CLOCK_THREAD_CPUTIME_ID`, as `peers.cpp`).
#[cfg(target_os = "linux")]
pub fn thread_cpu_ns() -> f64 {
    use std::os::raw::{c_int, c_long};
    #[repr(C)]
    struct Timespec {
        tv_sec: c_long,
        tv_nsec: c_long,
    }
    extern "C" {
        fn clock_gettime(clock: c_int, ts: *mut Timespec) -> c_int;
    }
    const CLOCK_THREAD_CPUTIME_ID: c_int = 3;
    let mut ts = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid `struct timespec` (two `long`s on Linux) for the call to fill.
    let rc = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    assert_eq!(rc, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID)");
    #[allow(clippy::cast_precision_loss, clippy::unnecessary_cast)]
    let ns = ts.tv_sec as f64 * 1e9 + ts.tv_nsec as f64;
    ns
}

/// Elsewhere the wall clock stands in.
#[cfg(not(target_os = "linux"))]
pub fn thread_cpu_ns() -> f64 {
    use std::sync::OnceLock;
    static START: OnceLock<Instant> = OnceLock::new();
    START.get_or_init(Instant::now).elapsed().as_secs_f64() * 1e9
}

/// The median of the rounds.
pub fn median(mut x: Vec<f64>) -> f64 {
    x.sort_by(f64::total_cmp);
    x[x.len() / 2]
}
