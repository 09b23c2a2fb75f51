//! Ratios of two timings that a shared, noisy machine cannot skew: see [`interleaved`].

use std::time::Instant;

/// `(median of time(b) / time(a), median time of a in ns)` over rounds in which the two are
/// timed back to back (alternating which goes first), so that the machine's load, which drifts
/// over seconds on a shared machine, cancels in each ratio.
pub fn interleaved(mut a: impl FnMut(), mut b: impl FnMut()) -> (f64, f64) {
    const CALLS: u32 = 20_000;
    const ROUNDS: usize = 101;
    let time = |f: &mut dyn FnMut()| {
        let start = Instant::now();
        for _ in 0..CALLS {
            f();
        }
        start.elapsed().as_secs_f64() / f64::from(CALLS)
    };
    for _ in 0..5 {
        time(&mut a);
        time(&mut b);
    }
    let mut ratios = Vec::with_capacity(ROUNDS);
    let mut a_times = Vec::with_capacity(ROUNDS);
    for round in 0..ROUNDS {
        let (l, p) = if round % 2 == 0 {
            let l = time(&mut a);
            (l, time(&mut b))
        } else {
            let p = time(&mut b);
            (time(&mut a), p)
        };
        ratios.push(p / l);
        a_times.push(l);
    }
    ratios.sort_by(f64::total_cmp);
    a_times.sort_by(f64::total_cmp);
    (ratios[ROUNDS / 2], a_times[ROUNDS / 2] * 1e9)
}
