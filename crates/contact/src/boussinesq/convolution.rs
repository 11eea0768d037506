//! Exact (non-periodic) discrete convolution `u_i = Σ_j f(x_i − x_j, y_i − y_j) p_j`
//! (seed 004 eq. (4)) by zero-padded FFT (SPEC §2.5, Toeplitz structure of the kernel table).
//!
//! The kernel `f` is even in `x̄` and `ȳ`, so its cyclic embedding is real-even and its DFT is
//! real: only one real kernel spectrum is stored, pre-transformed once. Along `x` the FFT
//! length `nfx ≥ 2nx − 1` is a fast 5-smooth even size (linear convolution, no wrap-around).
//! Two real rows are packed into one complex FFT (`z = p_a + i p_b`) and separated by
//! conjugate symmetry, so only `⌈ny/2⌉` complex FFTs are done each way. Along `y` either
//!
//! * [`ConvolutionMode::FftXDirectY`]: the `ny × ny` real symmetric Toeplitz sum is applied
//!   per `x` frequency (faster only for very small `ny`, see [`AUTO_DIRECT_Y_MAX_NY`]), or
//! * [`ConvolutionMode::Fft2d`]: a second zero-padded FFT along `y` (length `nfy ≥ 2ny − 1`).
//!
//! All buffers and FFT scratch live in [`Convolver`]; [`Convolver::apply`] does not allocate.

use super::influence::InfluenceTable;
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

type C64 = Complex<f64>;

/// How the convolution is evaluated along `y`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ConvolutionMode {
    /// [`ConvolutionMode::FftXDirectY`] for `ny ≤` [`AUTO_DIRECT_Y_MAX_NY`], else
    /// [`ConvolutionMode::Fft2d`] (threshold measured on this project's machines).
    #[default]
    Auto,
    /// Zero-padded 2-D FFT (rows then columns).
    Fft2d,
    /// FFT along `x`, direct Toeplitz sum along `y` in the `x`-frequency domain.
    FftXDirectY,
}

/// Largest `ny` for which [`ConvolutionMode::Auto`] uses the direct sum along `y`.
///
/// Measured (bench `convolution_*`, one `u = f * p`, 2-core shared machine): 350 × 3: equal;
/// 350 × 5: direct 2× faster; 350 × 9: 2-D ≈ 15 % faster; 1024 × 16: 2-D 1.6× faster;
/// 1024 × 64: 2-D 3.8× faster (0.82 ms vs 3.1 ms). rustfft's small-size kernels make the
/// 2-D transform cheap already at `nfy = 18`.
pub const AUTO_DIRECT_Y_MAX_NY: usize = 8;

/// Frequencies per tile of the blocked transposes between the packed rows (`[pair][k]`) and
/// the column-major spectra (`[k][j]`) of [`ConvolutionMode::Fft2d`]: 16 complex values are
/// four cache lines of a row, so a tile of all row pairs stays in L1/L2 and each page of the
/// rows is visited once per tile instead of once per frequency.
const TRANSPOSE_TILE: usize = 16;

/// Smallest even integer `≥ n` with no prime factor other than 2, 3, 5.
pub fn fast_fft_len(n: usize) -> usize {
    let mut m = n.max(2);
    loop {
        if m.is_multiple_of(2) {
            let mut r = m;
            for p in [2, 3, 5] {
                while r.is_multiple_of(p) {
                    r /= p;
                }
            }
            if r == 1 {
                return m;
            }
        }
        m += 1;
    }
}

enum Along {
    DirectY {
        /// Real kernel spectrum, `[d][k]`, `d < ny`, `k < half` (includes normalisation).
        kernel: Vec<f64>,
        /// Output spectrum `[j][k]`.
        out: Vec<C64>,
    },
    Fft2d {
        nfy: usize,
        fft_y: Arc<dyn Fft<f64>>,
        ifft_y: Arc<dyn Fft<f64>>,
        /// Real kernel spectrum `[k][ky]`, `k < half`, `ky < nfy` (includes normalisation).
        kernel: Vec<f64>,
    },
}

/// Sizes and strides of one grid's convolution.
#[derive(Debug, Clone, Copy)]
struct Shape {
    nx: usize,
    ny: usize,
    /// FFT length along `x`.
    nfx: usize,
    /// Stored frequencies `nfx/2 + 1` of the real spectra.
    half: usize,
    /// Packed row pairs `⌈ny/2⌉`.
    npairs: usize,
    /// Row stride of `rows`: `nfx` plus a small pad so that the rows do not all map to the
    /// same cache sets (nfx is often a power of two).
    rs: usize,
}

/// Pre-transformed kernel and work buffers for `u = f * p` on one grid.
pub struct Convolver {
    shape: Shape,
    fft_x: Arc<dyn Fft<f64>>,
    ifft_x: Arc<dyn Fft<f64>>,
    /// Packed rows, `npairs × rs` (first `nfx` entries of each row used).
    rows: Vec<C64>,
    /// Whether packed row pair `m` holds a non-zero value (an all-zero pair, e.g. pressure
    /// rows outside the contact, has an all-zero spectrum: its FFT is skipped).
    nonzero_pairs: Vec<bool>,
    /// Separated `x` spectra, `[j][k]` (direct-y) or `[k][j]` with stride `nfy` (2-D).
    spec: Vec<C64>,
    scratch: Vec<C64>,
    along: Along,
    mode: ConvolutionMode,
}

impl std::fmt::Debug for Convolver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Convolver")
            .field("nx", &self.shape.nx)
            .field("ny", &self.shape.ny)
            .field("nfx", &self.shape.nfx)
            .field("mode", &self.mode)
            .finish()
    }
}

impl Convolver {
    /// Pre-transform the kernel `table` and allocate all buffers.
    pub fn new(table: &InfluenceTable, mode: ConvolutionMode) -> Self {
        let (nx, ny) = (table.nx(), table.ny());
        let mode = match mode {
            ConvolutionMode::Auto if ny <= AUTO_DIRECT_Y_MAX_NY => ConvolutionMode::FftXDirectY,
            ConvolutionMode::Auto => ConvolutionMode::Fft2d,
            m => m,
        };
        let nfx = fast_fft_len(2 * nx - 1);
        let half = nfx / 2 + 1;
        let npairs = ny.div_ceil(2);
        let mut planner = FftPlanner::<f64>::new();
        let fft_x = planner.plan_fft_forward(nfx);
        let ifft_x = planner.plan_fft_inverse(nfx);
        let mut scratch_len = fft_x
            .get_inplace_scratch_len()
            .max(ifft_x.get_inplace_scratch_len());

        // Real-even x spectra of every kernel row d = 0..ny (f(m, d) = f(−m, d)).
        let zero = C64::new(0.0, 0.0);
        let mut tmp = vec![zero; nfx];
        let mut sc = vec![zero; fft_x.get_inplace_scratch_len()];
        let mut row_spec = vec![0.0; ny * half]; // [d][k], unnormalised
        for d in 0..ny {
            let row = table.row(d as isize);
            tmp.fill(zero);
            for m in 0..nx {
                let v = C64::new(row[nx - 1 + m], 0.0);
                tmp[m] = v;
                if m > 0 {
                    tmp[nfx - m] = v;
                }
            }
            fft_x.process_with_scratch(&mut tmp, &mut sc);
            for k in 0..half {
                row_spec[d * half + k] = tmp[k].re;
            }
        }

        let (along, spec_len) = match mode {
            ConvolutionMode::FftXDirectY | ConvolutionMode::Auto => {
                // 0.5: the packed-row separation below yields 2·P.
                let s = 0.5 / nfx as f64;
                let kernel: Vec<f64> = row_spec.iter().map(|v| s * v).collect(); // [d][k]
                (
                    Along::DirectY {
                        kernel,
                        out: vec![zero; half * ny],
                    },
                    half * ny,
                )
            }
            ConvolutionMode::Fft2d => {
                let nfy = fast_fft_len(2 * ny - 1);
                let fft_y = planner.plan_fft_forward(nfy);
                let ifft_y = planner.plan_fft_inverse(nfy);
                scratch_len = scratch_len
                    .max(fft_y.get_inplace_scratch_len())
                    .max(ifft_y.get_inplace_scratch_len());
                let mut col = vec![zero; nfy];
                let mut scy = vec![zero; fft_y.get_inplace_scratch_len()];
                let s = 0.5 / (nfx as f64 * nfy as f64);
                let mut kernel = vec![0.0; half * nfy];
                for k in 0..half {
                    col.fill(zero);
                    for d in 0..ny {
                        let v = C64::new(row_spec[d * half + k], 0.0);
                        col[d] = v;
                        if d > 0 {
                            col[nfy - d] = v;
                        }
                    }
                    fft_y.process_with_scratch(&mut col, &mut scy);
                    for ky in 0..nfy {
                        kernel[k * nfy + ky] = s * col[ky].re;
                    }
                }
                (
                    Along::Fft2d {
                        nfy,
                        fft_y,
                        ifft_y,
                        kernel,
                    },
                    half * nfy,
                )
            }
        };
        Self {
            shape: Shape {
                nx,
                ny,
                nfx,
                half,
                npairs,
                rs: nfx + 4,
            },
            fft_x,
            ifft_x,
            rows: vec![zero; npairs * (nfx + 4)],
            nonzero_pairs: vec![false; npairs],
            spec: vec![zero; spec_len],
            scratch: vec![zero; scratch_len],
            along,
            mode,
        }
    }

    /// Resolved evaluation mode (never `Auto`).
    pub fn mode(&self) -> ConvolutionMode {
        self.mode
    }

    /// FFT length along `x`.
    pub fn fft_len_x(&self) -> usize {
        self.shape.nfx
    }

    /// `u = f * p` on the grid (both of length `nx·ny`, x fastest). No allocation.
    ///
    /// # Panics
    /// If `p` or `u` does not have `nx·ny` entries.
    pub fn apply(&mut self, p: &[f64], u: &mut [f64]) {
        let shape = self.shape;
        assert_eq!(p.len(), shape.nx * shape.ny, "pressure length");
        assert_eq!(u.len(), shape.nx * shape.ny, "displacement length");
        let layout = self.spectrum_layout();

        self.transform_rows(p);
        self.separate_spectra(layout);

        // Step 3: kernel product along y.
        let out: &[C64] = match &mut self.along {
            Along::DirectY { kernel, out } => {
                direct_y_product(shape, kernel, &self.spec, out);
                out
            }
            Along::Fft2d {
                fft_y,
                ifft_y,
                kernel,
                ..
            } => {
                fft_y.process_with_scratch(&mut self.spec, &mut self.scratch);
                for (s, &kv) in self.spec.iter_mut().zip(kernel.iter()) {
                    *s *= kv;
                }
                ifft_y.process_with_scratch(&mut self.spec, &mut self.scratch);
                &self.spec
            }
        };

        repack_spectra(shape, layout, out, &mut self.rows);
        self.inverse_rows(u);
    }

    /// Strides `(sj, sk)` of row `j` and frequency `k` in the separated spectra: `[j][k]`
    /// (direct-y, k contiguous) or `[k][j]` with stride nfy (2-D, columns contiguous for the
    /// y FFTs).
    fn spectrum_layout(&self) -> (usize, usize) {
        match &self.along {
            Along::DirectY { .. } => (self.shape.half, 1),
            Along::Fft2d { nfy, .. } => (1, *nfy),
        }
    }

    /// Step 1: pack rows 2m, 2m+1 into z = p_a + i p_b, zero padded to nfx, and FFT them along x
    /// (all-zero pairs are left zero: their spectrum).
    fn transform_rows(&mut self, p: &[f64]) {
        let Shape {
            nx,
            ny,
            nfx,
            npairs,
            rs,
            ..
        } = self.shape;
        let zero = C64::new(0.0, 0.0);
        for m in 0..npairs {
            let z = &mut self.rows[m * rs..m * rs + nfx];
            let a = &p[2 * m * nx..(2 * m + 1) * nx];
            if 2 * m + 1 < ny {
                let b = &p[(2 * m + 1) * nx..(2 * m + 2) * nx];
                for ((zi, &ai), &bi) in z.iter_mut().zip(a).zip(b) {
                    *zi = C64::new(ai, bi);
                }
            } else {
                for (zi, &ai) in z.iter_mut().zip(a) {
                    *zi = C64::new(ai, 0.0);
                }
            }
            z[nx..].fill(zero);
            self.nonzero_pairs[m] = z[..nx].iter().any(|&v| v != zero);
        }
        for m in 0..npairs {
            if self.nonzero_pairs[m] {
                self.fft_x
                    .process_with_scratch(&mut self.rows[m * rs..m * rs + nfx], &mut self.scratch);
            }
        }
    }

    /// Step 2: separate the two real spectra (2·P_a = Z_k + conj Z_{N−k}, 2·P_b = −i(…−…))
    /// into `spec` with the strides `(sj, sk)` of [`Self::spectrum_layout`].
    fn separate_spectra(&mut self, (sj, sk): (usize, usize)) {
        let Shape {
            ny,
            nfx,
            half,
            npairs,
            rs,
            ..
        } = self.shape;
        if sk == 1 {
            // [j][k]: pair-major loop, contiguous writes.
            for m in 0..npairs {
                let z = &self.rows[m * rs..m * rs + nfx];
                let has_b = 2 * m + 1 < ny;
                for k in 0..half {
                    let zk = z[k];
                    let zc = z[(nfx - k) % nfx].conj();
                    self.spec[2 * m * sj + k] = zk + zc;
                    if has_b {
                        let d = zk - zc;
                        self.spec[(2 * m + 1) * sj + k] = C64::new(d.im, -d.re);
                    }
                }
            }
        } else {
            // [k][j]: a transpose, done in tiles of TRANSPOSE_TILE frequencies so that each
            // packed row is read in whole cache lines (and few pages) per tile.
            for k0 in (0..half).step_by(TRANSPOSE_TILE) {
                let k1 = (k0 + TRANSPOSE_TILE).min(half);
                for m in 0..npairs {
                    let z = &self.rows[m * rs..m * rs + nfx];
                    for k in k0..k1 {
                        let zk = z[k];
                        let zc = z[(nfx - k) % nfx].conj();
                        let col = &mut self.spec[k * sk..(k + 1) * sk];
                        col[2 * m] = zk + zc;
                        if 2 * m + 1 < ny {
                            let d = zk - zc;
                            col[2 * m + 1] = C64::new(d.im, -d.re);
                        }
                    }
                }
                for k in k0..k1 {
                    self.spec[k * sk + ny..(k + 1) * sk].fill(C64::new(0.0, 0.0));
                }
            }
        }
    }

    /// End of step 4: inverse FFT of the packed rows along x; row 2m of `u` is the real part,
    /// row 2m+1 the imaginary part.
    fn inverse_rows(&mut self, u: &mut [f64]) {
        let Shape {
            nx,
            ny,
            nfx,
            npairs,
            rs,
            ..
        } = self.shape;
        for m in 0..npairs {
            self.ifft_x
                .process_with_scratch(&mut self.rows[m * rs..m * rs + nfx], &mut self.scratch);
        }
        for m in 0..npairs {
            let w = &self.rows[m * rs..m * rs + nx];
            for (ui, wi) in u[2 * m * nx..(2 * m + 1) * nx].iter_mut().zip(w) {
                *ui = wi.re;
            }
            if 2 * m + 1 < ny {
                for (ui, wi) in u[(2 * m + 1) * nx..(2 * m + 2) * nx].iter_mut().zip(w) {
                    *ui = wi.im;
                }
            }
        }
    }
}

/// Step 3, direct-y: U_j = Σ_j' K_|j−j'| ⊙ P_j' (elementwise over k: vectorisable),
/// spectra `[j][k]`.
fn direct_y_product(shape: Shape, kernel: &[f64], spec: &[C64], out: &mut [C64]) {
    let (ny, half) = (shape.ny, shape.half);
    for j in 0..ny {
        let o = &mut out[j * half..(j + 1) * half];
        o.fill(C64::new(0.0, 0.0));
        for jp in 0..ny {
            let d = j.abs_diff(jp);
            let kr = &kernel[d * half..(d + 1) * half];
            let sp = &spec[jp * half..(jp + 1) * half];
            for ((ov, &kv), sv) in o.iter_mut().zip(kr).zip(sp) {
                ov.re += kv * sv.re;
                ov.im += kv * sv.im;
            }
        }
    }
}

/// Step 4: repack W = U_a + i U_b (Hermitian halves) of the product spectra `out`
/// (strides `(sj, sk)`) into the rows, ready for the inverse FFT along x.
fn repack_spectra(shape: Shape, (sj, sk): (usize, usize), out: &[C64], rows: &mut [C64]) {
    let Shape {
        ny,
        nfx,
        half,
        npairs,
        rs,
        ..
    } = shape;
    let zero = C64::new(0.0, 0.0);
    let repack = |ua: C64, ub: C64| {
        (
            C64::new(ua.re - ub.im, ua.im + ub.re),
            C64::new(ua.re + ub.im, ub.re - ua.im),
        )
    };
    if sk == 1 {
        for m in 0..npairs {
            let w = &mut rows[m * rs..m * rs + nfx];
            let has_b = 2 * m + 1 < ny;
            for k in 0..half {
                let ua = out[2 * m * sj + k];
                let ub = if has_b {
                    out[(2 * m + 1) * sj + k]
                } else {
                    zero
                };
                let (lo, hi) = repack(ua, ub);
                w[k] = lo;
                if k > 0 && 2 * k < nfx {
                    w[nfx - k] = hi;
                }
            }
        }
    } else {
        // The transpose back, in tiles of TRANSPOSE_TILE frequencies (see `separate_spectra`).
        for k0 in (0..half).step_by(TRANSPOSE_TILE) {
            let k1 = (k0 + TRANSPOSE_TILE).min(half);
            for m in 0..npairs {
                let w = &mut rows[m * rs..m * rs + nfx];
                for k in k0..k1 {
                    let ua = out[k * sk + 2 * m];
                    let ub = if 2 * m + 1 < ny {
                        out[k * sk + 2 * m + 1]
                    } else {
                        zero
                    };
                    let (lo, hi) = repack(ua, ub);
                    w[k] = lo;
                    if k > 0 && 2 * k < nfx {
                        w[nfx - k] = hi;
                    }
                }
            }
        }
    }
}

/// Reference direct double sum `u_i = Σ_j f_ij p_j` (O(N²)), seed 004 eq. (4).
///
/// # Panics
/// If `p` or `u` does not have `nx·ny` entries.
pub fn direct_convolution(table: &InfluenceTable, p: &[f64], u: &mut [f64]) {
    let (nx, ny) = (table.nx(), table.ny());
    assert_eq!(p.len(), nx * ny);
    assert_eq!(u.len(), nx * ny);
    u.fill(0.0);
    for jp in 0..ny {
        for ip in 0..nx {
            let v = p[jp * nx + ip];
            if v != 0.0 {
                accumulate_cell(table, ip, jp, v, u);
            }
        }
    }
}

/// `u += v · f(· − x_i0, · − y_j0)`: displacement of all cells due to pressure `v` on cell
/// `(i0, j0)` (used for sparse updates).
#[inline]
pub fn accumulate_cell(table: &InfluenceTable, i0: usize, j0: usize, v: f64, u: &mut [f64]) {
    accumulate_cells(table, &[(j0 * table.nx() + i0, v)], 1.0, u);
}

/// [`accumulate_cell`] for each `(k, v)` of `cells` (cell index `k = j0·nx + i0`, pressure
/// `scale · v`), row by row of `u`: each row of `u` stays in cache while every cell adds to
/// it, in the order of `cells` (the same sums as one [`accumulate_cell`] per cell).
pub fn accumulate_cells(table: &InfluenceTable, cells: &[(usize, f64)], scale: f64, u: &mut [f64]) {
    let (nx, ny) = (table.nx(), table.ny());
    for j in 0..ny {
        let u_row = &mut u[j * nx..(j + 1) * nx];
        for &(k, v) in cells {
            let (i0, j0) = (k % nx, k / nx);
            let v = scale * v;
            let row = table.row(j as isize - j0 as isize);
            // row[m + nx − 1] = f(m), m = i − i0 ∈ [−i0, nx − 1 − i0].
            let seg = &row[nx - 1 - i0..2 * nx - 1 - i0];
            for (ui, &f) in u_row.iter_mut().zip(seg) {
                *ui += v * f;
            }
        }
    }
}
