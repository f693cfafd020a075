//! The only rayon code of the solver: force elements (contacts above all) evaluated in
//! parallel into an indexed buffer, then summed serially in index order by the caller — so
//! every thread count gives the same bits (SPEC §8; a test compares 1 and 2 threads).
//!
//! Parallelism is a run-time setting ([`Parallelism`]), not a build feature: one build tests
//! both paths.

use std::sync::Arc;

/// How many threads evaluate force elements.
#[derive(Debug, Clone, Default)]
pub struct Parallelism {
    pool: Option<Arc<rayon::ThreadPool>>,
}

/// The most worker threads a run may ask for. Each thread reserves its own stack, so a count
/// far beyond the machine's cores (`NTHREADS = 1E6`) fails to start rather than running
/// faster; callers refuse a larger count before building the pool.
pub const MAX_THREADS: usize = 1024;

impl Parallelism {
    /// Serial evaluation.
    pub fn serial() -> Self {
        Self { pool: None }
    }

    /// `threads` worker threads (1 is serial). An error if the pool cannot be made.
    pub fn with_threads(threads: usize) -> Result<Self, rayon::ThreadPoolBuildError> {
        if threads <= 1 {
            return Ok(Self::serial());
        }
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()?;
        Ok(Self {
            pool: Some(Arc::new(pool)),
        })
    }

    /// Worker threads in use (1 when serial).
    pub fn threads(&self) -> usize {
        self.pool.as_ref().map_or(1, |p| p.current_num_threads())
    }

    /// `f` over `0..count`, results in index order, whatever the thread count.
    pub fn map_indexed<R: Send>(
        &self,
        count: usize,
        f: impl Fn(usize) -> R + Sync + Send,
    ) -> Vec<R> {
        match &self.pool {
            None => (0..count).map(f).collect(),
            Some(pool) => pool.install(|| {
                use rayon::prelude::*;
                (0..count).into_par_iter().map(f).collect()
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_keep_their_index_order_at_any_thread_count() {
        let f = |k: usize| (k as f64).sqrt().sin();
        let serial = Parallelism::serial().map_indexed(1000, f);
        let two = Parallelism::with_threads(2).unwrap();
        assert_eq!(two.threads(), 2);
        let parallel = two.map_indexed(1000, f);
        assert!(
            serial
                .iter()
                .zip(&parallel)
                .all(|(a, b)| a.to_bits() == b.to_bits())
        );
    }
}
