//! collide's physics for the page of `collide view`: the library without its command line,
//! behind a plain C interface, compiled to `wasm32-unknown-unknown` by `wasm/build.sh` (no
//! imports, no JavaScript glue: the page instantiates it from bytes, which works from `file://`).
//!
//! The page writes a request (JSON, UTF-8) into memory from `alloc`, calls `call` with its place
//! and length (which frees it), and reads the answer (JSON, `collide::view::api`) of the returned
//! length at `answer`.

use std::cell::RefCell;

thread_local! {
    /// The last answer, kept until the next call.
    static ANSWER: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
}

/// Memory for a request of `len` bytes.
#[unsafe(no_mangle)]
pub extern "C" fn alloc(len: usize) -> *mut u8 {
    let mut buffer = Vec::<u8>::with_capacity(len.max(1));
    let ptr = buffer.as_mut_ptr();
    std::mem::forget(buffer);
    ptr
}

/// Answers the request of `len` bytes at `ptr` (memory from `alloc(len)`, freed here); returns
/// the answer's length, its bytes are at `answer()`.
///
/// # Safety
/// `ptr` must come from `alloc(len)` and hold `len` written bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn call(ptr: *mut u8, len: usize) -> usize {
    // SAFETY: the caller passes memory from `alloc(len)` with `len` bytes written.
    let bytes = unsafe { Vec::from_raw_parts(ptr, len, len.max(1)) };
    let answer = collide::view::api::call(&String::from_utf8_lossy(&bytes));
    ANSWER.with(|a| {
        *a.borrow_mut() = answer.into_bytes();
        a.borrow().len()
    })
}

/// Where the last answer's bytes are.
#[unsafe(no_mangle)]
pub extern "C" fn answer() -> *const u8 {
    ANSWER.with(|a| a.borrow().as_ptr())
}
