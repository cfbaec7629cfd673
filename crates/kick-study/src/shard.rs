//! Shards as row ranges: shard I of N of an experiment (or sweep) is rows
//! `floor(I*rows/N) .. floor((I+1)*rows/N)`; the files a shard writes and
//! their merge are kick-store's.

use std::ops::Range;

/// A `--shard I/N` that is not one, naming the flag and what was given.
#[derive(Debug, thiserror::Error)]
#[error("`{flag}` = `{given}`: {message}")]
pub struct ShardFlagError {
    pub flag: String,
    pub given: String,
    pub message: String,
}

/// Shard `index` of `count`, both from 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: u64,
    pub count: u64,
}

impl Shard {
    /// Parse `I/N` (0 <= I < N) given as `flag`.
    pub fn parse(given: &str, flag: &str) -> Result<Shard, ShardFlagError> {
        let error = |message: String| ShardFlagError { flag: flag.into(), given: given.into(), message };
        let (i, n) = given.split_once('/').ok_or_else(|| error("expected I/N, e.g. 0/4 (shards numbered from 0)".into()))?;
        let number = |s: &str, what: &str| {
            s.trim().parse::<u64>().map_err(|e| match e.kind() {
                // Digits beyond u64: too large, not malformed.
                std::num::IntErrorKind::PosOverflow => {
                    error(format!("{what} `{s}` is too large (at most {} shards)", crate::experiment::MAX_SCENARIOS))
                }
                _ => error(format!("{what} `{s}` is not a whole number >= 0")),
            })
        };
        let (index, count) = (number(i, "shard index")?, number(n, "shard count")?);
        if count == 0 {
            return Err(error("the shard count must be at least 1".into()));
        }
        if count > crate::experiment::MAX_SCENARIOS {
            return Err(error(format!("more than {} shards", crate::experiment::MAX_SCENARIOS)));
        }
        if index >= count {
            return Err(error(format!("shard index {index} out of 0..{count}: shards are numbered from 0 to {}", count - 1)));
        }
        Ok(Shard { index, count })
    }

    /// Rows `floor(I*rows/N) .. floor((I+1)*rows/N)` of an experiment of `rows` rows.
    pub fn rows(&self, rows: u64) -> Range<u64> {
        let at = |i: u64| (u128::from(i) * u128::from(rows) / u128::from(self.count)) as u64;
        at(self.index)..at(self.index + 1)
    }

    /// `NAME.shard-I-of-N.h5`.
    pub fn file_name(&self, experiment: &str) -> String {
        format!("{experiment}.shard-{}-of-{}.h5", self.index, self.count)
    }
}

/// FNV-1a (64 bit) of the experiment text, as `fnv1a64:` and 16 hex digits:
/// tells parts of different experiment files apart (the text itself is in
/// every part's provenance and compared too).
pub fn fingerprint(text: &str) -> String {
    let hash = text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3));
    format!("fnv1a64:{hash:016x}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_cover_every_row_once_in_near_equal_slices() {
        for rows in [0u64, 1, 2, 7, 10, 4096, 100_003] {
            for count in [1u64, 2, 3, 7, 16] {
                let mut next = 0;
                for index in 0..count {
                    let r = Shard { index, count }.rows(rows);
                    assert_eq!(r.start, next, "{rows} rows, {index}/{count}");
                    let len = r.end - r.start;
                    assert!(len == rows / count || len == rows / count + 1, "{rows} rows, {index}/{count}: {len}");
                    next = r.end;
                }
                assert_eq!(next, rows);
            }
        }
        // floor(I*rows/N): 10 rows in 3 shards are 0..3, 3..6, 6..10.
        let slices: Vec<_> = (0..3).map(|index| Shard { index, count: 3 }.rows(10)).collect();
        assert_eq!(slices, [0..3, 3..6, 6..10]);
        // No overflow at the largest experiment.
        let big = crate::experiment::MAX_SCENARIOS;
        assert_eq!(Shard { index: big - 1, count: big }.rows(big), big - 1..big);
    }

    #[test]
    fn bad_shard_flags_are_refused_by_name() {
        assert_eq!(Shard::parse("2/5", "--shard").unwrap(), Shard { index: 2, count: 5 });
        for (given, says) in [
            ("3", "expected I/N"),
            ("5/5", "out of 0..5"),
            ("1/0", "at least 1"),
            ("-1/4", "not a whole number"),
            ("a/4", "not a whole number"),
            ("1/4.5", "not a whole number"),
            ("0/99999999999999999999", "too large"),
        ] {
            let message = Shard::parse(given, "--shard").unwrap_err().to_string();
            assert!(message.starts_with(&format!("`--shard` = `{given}`")) && message.contains(says), "{given}: {message}");
        }
    }

    #[test]
    fn fingerprint_is_fnv1a_64() {
        // Published FNV-1a 64 test vectors.
        assert_eq!(fingerprint(""), "fnv1a64:cbf29ce484222325");
        assert_eq!(fingerprint("a"), "fnv1a64:af63dc4c8601ec8c");
        assert_eq!(fingerprint("foobar"), "fnv1a64:85944171f73967e8");
    }
}
