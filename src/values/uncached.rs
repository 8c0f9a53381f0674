//! A file written around the page cache (Linux's `O_DIRECT`): bytes go from a buffer of this
//! process to the disk, and the kernel copies none of them into memory of its own.
//!
//! Why: a table of a gigabyte written the usual way is first copied into the page cache, a page
//! of fresh memory for every 4 KiB. On this project's machine (a virtual machine whose host takes
//! back the memory a guest frees) that copy took 3 to 4 s of kernel time for the 1.78 GB of a 10
//! M-row planar sweep, as much as solving the rows, and `dd` was no faster (2.5-4.7 s, `sync` and
//! 2 s idle before each run; 0.3-0.5 s when memory freed a moment earlier was reused). Written
//! around the cache the same bytes took 0.23-0.5 s of kernel time (`dd oflag=direct`, 1.3-1.5 s
//! of wall clock: the disk's own pace, overlapped with the solving). See docs/benchmarks.md.
//!
//! Direct I/O asks that the buffer's address, the file offset and the length be multiples of
//! the device's logical block (512 or 4096 bytes): whole blocks of [`BLOCK`] bytes go directly,
//! and the last partial block goes through the page cache (`O_DIRECT` cleared for that write;
//! the block stays in the buffer and is written again, whole, if more bytes follow). A file
//! system that refuses `O_DIRECT` (tmpfs on older kernels, some FUSE and network file systems:
//! `EINVAL` when the flag is set, or at a write) gets the same bytes through the page cache.

use std::fs::File;
use std::io::{self, Write};
use std::mem::MaybeUninit;
use std::os::fd::AsRawFd;
use std::os::unix::fs::FileExt;

/// The alignment of a direct write's buffer, offset and length: 4096 covers every logical block
/// size in use (a 512-byte device takes it too).
pub const BLOCK: usize = 4096;

/// Bytes sent to the disk a write at a time (and the buffer's size): small enough to stay in a
/// core's cache (2 MiB of L2 here) while the rows are copied in and the disk reads them out; 1
/// MiB ran the 10 M-row planar sweep in 2.60-3.25 s, 8 MiB in 2.74-3.31 s (runs alternated).
const CAP: usize = 1 << 20;

/// A block's worth of bytes, aligned as direct I/O asks.
#[repr(C, align(4096))]
struct Block([MaybeUninit<u8>; BLOCK]);

/// A file being written, whole blocks around the page cache.
pub struct Uncached {
    file: File,
    /// The buffer: `CAP / BLOCK` blocks of capacity, never initialised as a whole (a small
    /// output costs only the pages written into).
    blocks: Vec<Block>,
    /// Bytes in the buffer, all initialised (`blocks`' first `len` bytes).
    len: usize,
    /// The file offset of the buffer's first byte (a multiple of `BLOCK`).
    at: u64,
    /// Whether `O_DIRECT` is on (off after a write the file system refused).
    direct: bool,
    /// Whether the buffer's bytes (a partial block) are in the file already (flushed, nothing
    /// written since).
    tail: bool,
}

impl Uncached {
    /// Writes `file` around the page cache from now on; the file back where its file system
    /// refuses `O_DIRECT` (tmpfs on older kernels, some FUSE and network file systems).
    pub fn new(file: File) -> Result<Uncached, File> {
        let out = Uncached::buffered(file, true);
        match out.set_direct(true) {
            Ok(()) => Ok(out),
            Err(_) => Err(out.file),
        }
    }

    /// The buffer over `file`, `direct` or not (the flag is not changed here).
    fn buffered(file: File, direct: bool) -> Uncached {
        Uncached {
            file,
            blocks: Vec::with_capacity(CAP / BLOCK),
            len: 0,
            at: 0,
            direct,
            tail: false,
        }
    }

    /// The file (for `fsync`, permissions).
    pub fn file(&self) -> &File {
        &self.file
    }

    /// Whether the writes still go around the page cache.
    pub fn is_direct(&self) -> bool {
        self.direct
    }

    /// The buffer's first `n` bytes (`n <= len`, so all written).
    fn filled(&self, n: usize) -> &[u8] {
        debug_assert!(n <= self.len);
        // SAFETY: the capacity holds CAP >= len >= n bytes, contiguous (a `Block` is its bytes,
        // no padding: size = align = BLOCK), and the first `len` were written by `write`.
        unsafe { std::slice::from_raw_parts(self.blocks.as_ptr().cast::<u8>(), n) }
    }

    /// Turns `O_DIRECT` on or off on the open file.
    fn set_direct(&self, on: bool) -> io::Result<()> {
        let fd = self.file.as_raw_fd();
        // SAFETY: F_GETFL and F_SETFL read and set the status flags of this file's own open
        // descriptor; no memory is passed.
        let flags = unsafe { libc::fcntl(fd, libc::F_GETFL) };
        if flags < 0 {
            return Err(io::Error::last_os_error());
        }
        let flags = if on {
            flags | libc::O_DIRECT
        } else {
            flags & !libc::O_DIRECT
        };
        // SAFETY: as above.
        if unsafe { libc::fcntl(fd, libc::F_SETFL, flags) } < 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    }

    /// Writes the buffer's first `n` bytes (whole blocks) at `at` and drops them from the
    /// buffer. A write the file system refuses (`EINVAL`) is made again through the page cache,
    /// and so is every later one.
    fn put(&mut self, n: usize) -> io::Result<()> {
        match self.file.write_all_at(self.filled(n), self.at) {
            Err(e) if self.direct && e.raw_os_error() == Some(libc::EINVAL) => {
                self.set_direct(false)?;
                self.direct = false;
                self.file.write_all_at(self.filled(n), self.at)?;
            }
            r => r?,
        }
        let base = self.blocks.as_mut_ptr().cast::<u8>();
        // SAFETY: both ranges lie in the first `len` bytes of the buffer (written); `copy`
        // allows them to overlap.
        unsafe { std::ptr::copy(base.add(n), base, self.len - n) };
        self.len -= n;
        self.at += n as u64;
        Ok(())
    }
}

impl Write for Uncached {
    fn write(&mut self, data: &[u8]) -> io::Result<usize> {
        if self.len == CAP {
            self.put(CAP)?;
        }
        let n = data.len().min(CAP - self.len);
        // SAFETY: `len + n <= CAP`, the buffer's capacity in bytes; `data` is another object.
        unsafe {
            std::ptr::copy_nonoverlapping(
                data.as_ptr(),
                self.blocks.as_mut_ptr().cast::<u8>().add(self.len),
                n,
            );
        }
        self.len += n;
        self.tail &= n == 0;
        Ok(n)
    }

    /// Writes every byte: the whole blocks directly, the last partial block through the page
    /// cache (kept in the buffer, so that later bytes rewrite its block whole, directly).
    fn flush(&mut self) -> io::Result<()> {
        let whole = self.len / BLOCK * BLOCK;
        if whole > 0 {
            self.put(whole)?;
        }
        if self.len > 0 && !self.tail {
            if self.direct {
                self.set_direct(false)?;
            }
            self.file.write_all_at(self.filled(self.len), self.at)?;
            if self.direct {
                self.set_direct(true)?;
            }
            self.tail = true;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bytes that show where each one came from (a misplaced block changes the file).
    fn pattern(n: usize, seed: u64) -> Vec<u8> {
        let mut x = seed;
        (0..n)
            .map(|_| {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (x >> 56) as u8
            })
            .collect()
    }

    /// Writes of every awkward size (a byte, a block less one, exactly the buffer, more than
    /// it) with flushes between some of them give the file their concatenation, byte for byte;
    /// the same with the buffering over a plain file where the file system refuses `O_DIRECT`.
    #[test]
    fn the_file_is_the_bytes_written_in_order() {
        let path =
            std::env::temp_dir().join(format!("collide-uncached-{}.bin", std::process::id()));
        let sizes = [
            1,
            BLOCK - 1,
            BLOCK,
            3 * BLOCK + 17,
            CAP,
            CAP - BLOCK + 5,
            2 * CAP + 1,
            5 * CAP + 3 * BLOCK,
            0,
            511,
            100_000,
        ];
        let mut expected = Vec::new();
        let direct;
        {
            // Where the file system refuses O_DIRECT, the same buffering over a plain file.
            let mut out = match Uncached::new(File::create(&path).unwrap()) {
                Ok(out) => out,
                Err(file) => Uncached::buffered(file, false),
            };
            for (i, &n) in sizes.iter().enumerate() {
                let bytes = pattern(n, i as u64);
                out.write_all(&bytes).unwrap();
                expected.extend_from_slice(&bytes);
                if i % 3 == 1 {
                    out.flush().unwrap();
                    assert_eq!(std::fs::read(&path).unwrap(), expected, "after write {i}");
                }
            }
            out.flush().unwrap();
            direct = out.is_direct();
        }
        let got = std::fs::read(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(got.len(), expected.len());
        assert!(got == expected, "the file differs from the bytes written");
        eprintln!("written around the page cache: {direct}");
    }
}
