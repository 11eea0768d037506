//! Byte serialisation of the full run state (state vector, integrator memory, accumulators) so
//! that a resumed run continues bit-for-bit. Little-endian, versioned, with a fingerprint of
//! the model so that a checkpoint cannot be applied to a different bearing.

use crate::error::DynError;

/// Format tag (02: integrator method tag and Rosenbrock-W state).
pub(crate) const MAGIC: &[u8; 8] = b"RDYNCK05";

/// Appends values to a byte buffer.
#[derive(Debug, Default)]
pub(crate) struct Writer {
    pub buf: Vec<u8>,
}

impl Writer {
    pub fn f64(&mut self, x: f64) {
        self.buf.extend_from_slice(&x.to_bits().to_le_bytes());
    }
    pub fn u64(&mut self, x: u64) {
        self.buf.extend_from_slice(&x.to_le_bytes());
    }
    pub fn slice(&mut self, v: &[f64]) {
        self.u64(v.len() as u64);
        for &x in v {
            self.f64(x);
        }
    }
}

/// Reads values back.
#[derive(Debug)]
pub(crate) struct Reader<'a> {
    pub buf: &'a [u8],
    pub pos: usize,
}

impl<'a> Reader<'a> {
    pub fn new(buf: &'a [u8]) -> Self {
        Self { buf, pos: 0 }
    }
    fn take8(&mut self) -> Result<[u8; 8], DynError> {
        let end = self.pos + 8;
        let s = self
            .buf
            .get(self.pos..end)
            .ok_or_else(|| DynError::Checkpoint("truncated data".into()))?;
        self.pos = end;
        let mut a = [0u8; 8];
        a.copy_from_slice(s);
        Ok(a)
    }
    pub fn f64(&mut self) -> Result<f64, DynError> {
        Ok(f64::from_bits(u64::from_le_bytes(self.take8()?)))
    }
    pub fn u64(&mut self) -> Result<u64, DynError> {
        Ok(u64::from_le_bytes(self.take8()?))
    }
    pub fn slice_into(&mut self, v: &mut [f64]) -> Result<(), DynError> {
        let n = self.u64()? as usize;
        if n != v.len() {
            return Err(DynError::Checkpoint(format!(
                "vector of {n} values where {} are expected",
                v.len()
            )));
        }
        for x in v.iter_mut() {
            *x = self.f64()?;
        }
        Ok(())
    }
    pub fn magic(&mut self) -> Result<(), DynError> {
        let a = self.take8()?;
        if &a != MAGIC {
            return Err(DynError::Checkpoint(
                "not a rolldyn dynamics checkpoint (or another format version)".into(),
            ));
        }
        Ok(())
    }
}
