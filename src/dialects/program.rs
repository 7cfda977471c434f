//! Program lines: what a block of a part program does to the active frame, in each
//! controller's own syntax, and the line that programs a given frame.
//!
//! A [`Program`] is the modal state a controller keeps between blocks (the active frame,
//! TwinCAT's programmed angles, SINUMERIK's angle mode); [`Program::line`] applies one block
//! and returns the next state, so a refused block leaves the caller's state as it was.
//! [`write_line`] is the inverse: the block that the same dialect's reader turns into a frame.
//! The syntax each dialect accepts is in that dialect's file (its `Family` implementation);
//! this module holds what is the same for all: the state, line ends and lengths, the checks
//! of a restored state and of a written line.

pub(crate) use super::family::FormSpec;
pub use super::family::{AxisChoice, Direct, DirectAxes, Feed, Plane, Positioning, Retract};
use super::family::{Block, Modal, Motion, MAX_VALUES};
use super::form;
pub use super::registry::Dialect;
use crate::kinematics::{Choice, Machine, Rule, MAX_AXES, VERIFY};
use crate::text::number::Out;
pub use crate::text::scan::LineError;
use crate::{Error, Frame, Vector};

/// The modal state of a program: what the blocks read so far have left active. The
/// default is nothing active.
///
/// ```
/// use cncrot::dialects::program::{Dialect, Program, Remark};
/// // The TwinCAT manual's example: ROT Z30, then AROT Z15, is a rotation of 45° about Z.
/// let (p, _) = Program::default().line(Dialect::Twincat, b"N65 ROT Z30").unwrap();
/// let (p, remark) = p.line(Dialect::Twincat, b"N90 AROT Z15").unwrap();
/// assert_eq!((p.angles, remark), ([0.0, 0.0, 45.0], Remark::Applied));
/// // Any other block of the program is passed over, the state unchanged.
/// assert_eq!(p.line(Dialect::Twincat, b"N100 G01 X10 F500").unwrap(), (p, Remark::Passed));
/// // A line that cannot be executed is refused with the column of its first bad character.
/// let e = p.line(Dialect::Twincat, b"ROT Z=R1").unwrap_err();
/// assert_eq!((e.error, e.column), (cncrot::Error::NotANumber, 7));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Program {
    /// The active frame (identity: nothing active).
    pub frame: Frame,
    /// TwinCAT's programmed angles `X Y Z` (its `AROT` adds angles, not matrices); a direct
    /// mode's rotary-axis positions (degrees; see [`Direct`]).
    pub angles: [f64; 3],
    /// The dialect of the lines read so far: a program speaks one.
    pub dialect: Option<Dialect>,
    /// SINUMERIK's frame angles in Euler mode (machine data 10600 = 2) instead of RPY: a
    /// setting of the machine that no block changes.
    pub euler: bool,
    /// Heidenhain's `CYCL DEF 19.1 A B C` are the positions of the rotary axes named so (a
    /// direct mode, as `PLANE AXIAL`) instead of spatial angles (as `PLANE SPATIAL`): a
    /// setting of the machine (iTNC 530 machine parameter 7500 bit 1 = 0, TNC 640
    /// kinematics configuration) that no block changes.
    pub axis_angles: bool,
    /// The datum shift the program made active (`CYCL DEF 7`, `TRANS DATUM`, `G52`, `G58`),
    /// in the workpiece axes before the tilt: part of `frame`'s origin, kept when the tilt
    /// is cancelled.
    pub shift: [f64; 3],
    /// The solution the active tilt's own words choose for the rotary axes (`SEQ±`,
    /// `_DIR`, `G53.1 P`); [`Program::axes`] follows it.
    pub choice: AxisChoice,
    /// How the program moves the machine to the active tilt (`STAY`, `TURN`, `MOVE`,
    /// `G53.1`, `G53.6`, `G253`; a `CYCLE800` swivels); stay when no tilt is active.
    pub positioning: Positioning,
    /// How the tool retracts before the rotary axes turn (`MB`, `_FR`); none while the
    /// positioning is stay.
    pub retract: Retract,
    /// The retraction's length in mm for [`Retract::Tool`] (positive), else 0.
    pub retract_mm: f64,
    /// How fast the rotary axes turn (`FMAX`, `F`); rapid while the positioning is stay.
    pub feed: Feed,
    /// The feed rate in mm/min for [`Feed::Rate`] (positive), else 0.
    pub feed_mm_min: f64,
    /// An active direct mode (`PLANE AXIAL`, `CYCLE800` direct, `G158` mode 2), its
    /// rotary-axis positions in `angles`. Its rotation follows from the machine: `frame`
    /// then holds the origin with the identity rotation, and [`Program::frame_on`] gives
    /// the frame.
    pub direct: Option<Direct>,
    /// The working plane the program selected (`G17`–`G19`; `G17` until one is).
    pub plane: Plane,
    /// The active tilt turns a free rotary table to the plane (Heidenhain `TABLE ROT`)
    /// instead of turning the coordinate system alone (`COORD ROT`, or no word): at a pose
    /// where the first rotary table from the workpiece is parallel to the tool,
    /// [`Program::axes`] turns it so that the machine makes the whole rotation. False while
    /// no tilt (or a direct mode) is active.
    pub table_rot: bool,
    /// The active tilt was set by a block that adds to the tilt before it (`PLANE
    /// RELATIV`, `G68.4`, a `CYCLE800` with `_ST` 1, `AROT`, `ATRANS`, `G158 P01…`,
    /// `CYCLE600` with `_ROT_AD` 1, TwinCAT's `AROT` of one axis): a translator writes the
    /// target's incremental form, so that a loop which repeats the block adds as often.
    /// False while no tilt (or a direct mode) is active.
    pub relative: bool,
}

/// What a block did, beside the state it leaves (`CNCROT_STATUS_PASSED` and
/// `CNCROT_STATUS_NOT_FOLLOWED` in C).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Remark {
    /// A command that concerns the frame was applied (the state may be the same: a
    /// `G53.1`, a cancel with nothing active).
    Applied,
    /// The block does not concern the frame (motion, tool, M and S words, program
    /// structure, comments, a blank line): the state is the one given, byte for byte.
    Passed,
    /// The block changes the frame in a way the library does not follow (a work-offset or
    /// preset selection, a table or frame-variable write, mirroring, scaling, an increment
    /// on an active direct mode, whose base is the machine's): the state is the one given,
    /// and may no longer be the control's.
    NotFollowed,
}

impl Program {
    /// Applies one block in `dialect` (any block of a program: see [`Remark`]); returns the
    /// next state and what the block did. Refused (with the column):
    /// another dialect than the program's ([`Error::BadArgument`]), a line longer than
    /// [`Dialect::max_line`] ([`Error::LineTooLong`]), an unknown, repeated or misplaced word
    /// ([`Error::UnknownWord`]), a variable or expression where a number must stand
    /// ([`Error::NotANumber`]), a missing word ([`Error::MissingWord`]), a malformed number
    /// ([`Error::Parse`]), and whatever the command's mathematics refuses.
    pub fn line(&self, dialect: Dialect, text: &[u8]) -> Result<(Program, Remark), LineError> {
        if self.dialect.is_some_and(|d| d != dialect) {
            return Err(LineError {
                error: Error::BadArgument,
                column: 1,
                expected: None,
            });
        }
        let text = block_of(dialect, text)?;
        let read = match dialect.read_line(&self.modal(), text) {
            // An increment on an active direct mode (`PLANE RELATIV` after `PLANE AXIAL`,
            // `AROT` after a direct `CYCLE800`): well formed, its base the machine's
            // rotation, not known here.
            Err(e) if e.error == Error::NotAvailable && self.direct.is_some() => Block::NotFollowed,
            r => r?,
        };
        let next = match read {
            Block::Frame(next) => next,
            Block::Passed => return Ok((*self, Remark::Passed)),
            Block::NotFollowed => return Ok((*self, Remark::NotFollowed)),
        };
        let untilted = next.frame == Frame::IDENTITY;
        // A tilt of zero that turns the axes (`PLANE … TURN` of zero angles, `PLANE RESET
        // TURN`, a `CYCLE800` of zero angles) keeps its way of moving: the machine turns to
        // the untilted plane.
        let positioning = next.positioning;
        // Only a tilt has a free table to turn, or was added to the one before.
        let tilted = next.frame.rotation != crate::IDENTITY && next.direct.is_none();
        let table_rot = next.table_rot && !untilted && next.direct.is_none();
        let stay = positioning == Positioning::Stay;
        let h = next.frame.to_homogeneous();
        if !h.iter().flatten().all(|x| x.is_finite()) {
            return Err(LineError {
                error: Error::OutOfRange,
                column: 1,
                expected: None,
            });
        }
        Ok((
            Program {
                frame: next.frame,
                angles: next.angles,
                dialect: Some(dialect),
                euler: next.euler,
                axis_angles: next.axis_angles,
                shift: next.shift,
                choice: next.choice,
                // Staying: no retraction, no feed.
                positioning,
                retract: if stay { Retract::None } else { next.retract },
                retract_mm: if stay { 0.0 } else { next.retract_mm },
                feed: if stay { Feed::Rapid } else { next.feed },
                feed_mm_min: if stay { 0.0 } else { next.feed_mm_min },
                direct: next.direct,
                plane: next.plane,
                table_rot,
                relative: next.relative && tilted,
            },
            Remark::Applied,
        ))
    }

    /// The rotary-axis positions the active tilt moves `machine` to, seen from `current`
    /// (degrees; axes the machine lacks are 0), as [`Machine::choose`] chooses them under the
    /// rule of the tilt's own choice words ([`Program::choice`]): `SEQ-`, `_DIR = -1` the
    /// lower angle of the master axis ([`Rule::Minus`]: in (−180°, 180°], whatever
    /// `current`), `SEQ+`, `_DIR = +1` the higher
    /// \[doc\], the master axis being a head's axis nearest the tool, else the axis nearest
    /// the machine base \[choice\]; without words Fanuc's own rule for `G53.1`
    /// ([`Rule::MasterFirst`]: its first rotation axis, a mixed machine's table axis, moving
    /// the least) \[doc\], else the solution closest to the current positions
    /// ([`Rule::Closest`]) — what SINUMERIK does for a frame \[doc\], Heidenhain without
    /// `SEQ` (the shortest way) \[doc\], and the library's default for the others (Syntec's
    /// `G53.1`, Haas's `G253`) \[choice\]. Heidenhain's `SEQ±`: the angles themselves,
    /// and [`Error::OutOfTravel`] where its side lies beyond the travel (see
    /// `heidenhain_seq`). Whole turns are unwound toward `current`, the travel
    /// limits and Hirth grids respected. No tilt active: the positions of the identity
    /// frame. A choice naming an axis the machine lacks: [`Error::BadArgument`].
    ///
    /// ```
    /// use cncrot::dialects::program::{Dialect, Program};
    /// use cncrot::kinematics::{Machine, RotaryAxis, Side};
    /// // A head turning about Z, then about Y.
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3])).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3])).unwrap();
    /// let (p, _) = Program::default().line(Dialect::Heidenhain, b"PLANE SPATIAL SPA+0 SPB+30 SPC+0").unwrap();
    /// // From C = 750°: C = 720°, B = 30°.
    /// let c = p.axes(&m, [750.0, 0.0, 0.0]).unwrap();
    /// assert!((c.axes[0] - 720.0).abs() < 1e-9 && (c.axes[1] - 30.0).abs() < 1e-9);
    /// ```
    pub fn axes(&self, machine: &Machine, current: [f64; 3]) -> Result<Choice, Error> {
        if let Some(d) = self.direct {
            return machine.commanded(direct_positions(&d, self.angles, machine)?, current);
        }
        // Axis k (1-based), or 0: the reference axis of a side (`SEQ±`, `_DIR`: the master
        // axis) or of a direction of travel (`G53.1 P1`/`P2`: the primary axis, the one
        // Fanuc's own rule moves first, that carries the other).
        let axis = |k: u8, reference: usize| -> Result<usize, Error> {
            let n = machine.axes().len();
            match usize::from(k) {
                0 => Ok(reference),
                k if k <= n => Ok(k - 1),
                _ => Err(Error::BadArgument),
            }
        };
        let rule = match self.choice {
            // Fanuc's own rule where the block names none (`G53.1`, `G53.1 P0`).
            AxisChoice::Closest
                if self.dialect == Some(Dialect::Fanuc) && !machine.axes().is_empty() =>
            {
                Rule::MasterFirst(fanuc_master(machine))
            }
            AxisChoice::Closest => Rule::Closest,
            _ if machine.axes().is_empty() => Rule::Closest,
            AxisChoice::Minus(k) => Rule::Minus(axis(k, master_axis(machine))?),
            AxisChoice::Plus(k) => Rule::Plus(axis(k, master_axis(machine))?),
            AxisChoice::PositiveTurn(k) => Rule::PositiveTurn(axis(k, fanuc_master(machine))?),
            AxisChoice::NegativeTurn(k) => Rule::NegativeTurn(axis(k, fanuc_master(machine))?),
        };
        let mut c = machine.choose(&self.frame.rotation, current, rule)?;
        if let (Some(Dialect::Heidenhain), Rule::Minus(k) | Rule::Plus(k)) = (self.dialect, rule) {
            heidenhain_seq(
                machine,
                &self.frame.rotation,
                &mut c,
                k,
                matches!(rule, Rule::Plus(_)),
            )?;
        }
        if self.table_rot && c.free {
            return table_turned(machine, &self.frame.rotation, c, current);
        }
        Ok(c)
    }

    /// What the families read and write.
    fn modal(&self) -> Modal {
        Modal {
            frame: self.frame,
            angles: self.angles,
            euler: self.euler,
            axis_angles: self.axis_angles,
            shift: self.shift,
            choice: self.choice,
            positioning: self.positioning,
            retract: self.retract,
            retract_mm: self.retract_mm,
            feed: self.feed,
            feed_mm_min: self.feed_mm_min,
            direct: self.direct,
            plane: self.plane,
            table_rot: self.table_rot,
            relative: self.relative,
        }
    }

    /// Whether a tilt is active: a frame other than the identity, or a direct mode.
    pub fn is_active(&self) -> bool {
        self.frame != Frame::IDENTITY || self.direct.is_some()
    }

    /// The active frame on `machine`: [`Program::frame`], or for a direct mode the frame
    /// the machine's kinematics gives with its rotary axes at the block's positions
    /// (the rotation of [`Machine::forward`]) about the block's origin. Errors: those of
    /// [`Program::check`], and for a direct mode those of [`Program::axes`].
    ///
    /// ```
    /// use cncrot::dialects::program::{Dialect, Program};
    /// use cncrot::kinematics::{Machine, RotaryAxis, Side};
    /// // A table: B about Y carrying C about Z.
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [0.0, 1.0, 0.0], [0.0; 3])).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [0.0; 3])).unwrap();
    /// let (p, _) = Program::default().line(Dialect::Heidenhain, b"PLANE AXIAL B+30").unwrap();
    /// // The table tilted by +30° about Y: the tool, fixed along the machine's Z, is along
    /// // Ry(-30°)·e_z = (-0.5, 0, 0.866) in the workpiece.
    /// let f = p.frame_on(&m).unwrap();
    /// assert!((f.rotation[0][2] + 0.5).abs() < 1e-15 && f.translation == [0.0; 3]);
    /// ```
    pub fn frame_on(&self, machine: &Machine) -> Result<Frame, Error> {
        self.check()?;
        let Some(d) = self.direct else {
            return Ok(self.frame);
        };
        let positions = direct_positions(&d, self.angles, machine)?;
        let rotation = machine.forward(positions)?.rotation;
        Ok(Frame {
            rotation,
            translation: self.frame.translation,
        })
    }

    /// Whether this state is one that reading lines can leave: finite, its frame a rotation,
    /// TwinCAT's rotation the one of its angles and no angles in the other dialects (a state
    /// restored from elsewhere is checked before use).
    ///
    /// ```
    /// use cncrot::dialects::program::{Dialect, Program};
    /// let (p, _) = Program::default().line(Dialect::Twincat, b"ROT Z30").unwrap();
    /// assert!(p.check().is_ok());
    /// assert!(Program { angles: [0.0, 0.0, 31.0], ..p }.check().is_err());
    /// ```
    pub fn check(&self) -> Result<(), Error> {
        let numbers = self
            .frame
            .translation
            .iter()
            .chain(&self.angles)
            .chain(&self.shift);
        if !numbers.into_iter().all(|x| x.is_finite()) {
            return Err(Error::NotFinite);
        }
        crate::check_rotation(&self.frame.rotation)?;
        let direct = match self.direct {
            None => true,
            Some(d) => {
                // As a reader leaves it: the rotation the machine's, the positions not
                // given zero, no choice words (the positions are the choice), in a
                // dialect whose direct mode names the axes so.
                let by = match self.dialect {
                    Some(Dialect::Heidenhain | Dialect::Syntec) => Some(DirectAxes::Letters),
                    Some(Dialect::Sinumerik) => Some(DirectAxes::Numbered),
                    _ => None,
                };
                self.frame.rotation == crate::IDENTITY
                    && d.given != 0
                    && d.given < 8
                    && (0..3).all(|k| d.given & (1 << k) != 0 || self.angles.get(k) == Some(&0.0))
                    && self.choice == AxisChoice::Closest
                    && by == Some(d.by)
            }
        };
        let consistent = direct
            && match self.dialect {
                Some(d) => d.consistent(&self.modal()),
                None => self.angles == [0.0; 3],
            }
            // `TABLE ROT` is Heidenhain's word, and only a tilt has a table to turn.
            && (!self.table_rot
                || (self.dialect == Some(Dialect::Heidenhain)
                    && self.direct.is_none()
                    && self.frame != Frame::IDENTITY))
            // Only a tilt was added to.
            && (!self.relative
                || (self.direct.is_none() && self.frame.rotation != crate::IDENTITY))
            && self.motion_consistent();
        if consistent {
            Ok(())
        } else {
            Err(Error::BadArgument)
        }
    }
}

impl Program {
    /// The state without a way of moving to its tilt: staying, no retraction, at rapid, as a
    /// reader leaves a tilt that moves no axis (the choice of solution kept). What a
    /// translator writes a block from or to where the axes are already at the plane.
    ///
    /// ```
    /// use cncrot::dialects::program::{Dialect, Positioning, Program, Retract};
    /// let p = Program::default();
    /// let (p, _) = p.line(Dialect::Heidenhain, b"PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB50 FMAX").unwrap();
    /// let s = p.staying();
    /// assert_eq!((s.positioning, s.retract, s.frame), (Positioning::Stay, Retract::None, p.frame));
    /// ```
    pub fn staying(&self) -> Program {
        Program {
            positioning: Positioning::Stay,
            retract: Retract::None,
            retract_mm: 0.0,
            feed: Feed::Rapid,
            feed_mm_min: 0.0,
            ..*self
        }
    }

    /// How the machine moves to the active tilt, as the tilt block says it.
    fn motion(&self) -> Motion {
        Motion {
            choice: self.choice,
            positioning: self.positioning,
            retract: self.retract,
            retract_mm: self.retract_mm,
            feed: self.feed,
            feed_mm_min: self.feed_mm_min,
            table_rot: self.table_rot,
            relative: false,
        }
    }

    /// Retraction and feed as a reader leaves them: none while staying, a retraction
    /// distance and a feed rate positive and finite.
    fn motion_consistent(&self) -> bool {
        let stay = self.positioning == Positioning::Stay;
        let (d, f) = (self.retract_mm, self.feed_mm_min);
        let retract = match self.retract {
            Retract::None => d == 0.0,
            Retract::Tool => !stay && d > 0.0 && d.is_finite(),
            _ => !stay && d == 0.0,
        };
        let feed = match self.feed {
            Feed::Rapid => f == 0.0,
            Feed::Rate => !stay && f > 0.0 && f.is_finite(),
            Feed::Auto => !stay && f == 0.0,
        };
        retract && feed
    }
}

/// A program line without its line end (`\n`, `\r\n`, `\r`: not part of the block), or
/// [`Error::LineTooLong`] beyond the dialect's longest block.
pub(crate) fn block_of(dialect: Dialect, text: &[u8]) -> Result<&[u8], LineError> {
    let text = match text {
        [rest @ .., b'\r', b'\n'] | [rest @ .., b'\n'] | [rest @ .., b'\r'] => rest,
        _ => text,
    };
    if text.len() > dialect.max_line() {
        return Err(LineError {
            error: Error::LineTooLong,
            column: dialect.max_line() + 1,
            expected: None,
        });
    }
    Ok(text)
}

/// The positions of `machine`'s rotary axes that a direct mode states: by place, or by
/// letter, each machine axis taking the position of its letter ([`axis_letters`]: the
/// one its direction is nearest, A for X, B for Y, C for Z) \[choice: a machine
/// description carries no axis names\]. A nonzero position for a letter or a place the
/// machine lacks: [`Error::BadArgument`].
pub(crate) fn direct_positions(
    d: &Direct,
    stated: [f64; 3],
    machine: &Machine,
) -> Result<[f64; 3], Error> {
    let mut positions = [0.0; 3];
    let mut taken = 0u8;
    let letters = axis_letters(machine);
    for k in 0..machine.axes().len() {
        let slot = match d.by {
            DirectAxes::Numbered => k,
            DirectAxes::Letters => letters.get(k).copied().unwrap_or(k),
        };
        if let (Some(p), Some(v)) = (positions.get_mut(k), stated.get(slot)) {
            *p = *v;
        }
        taken |= 1 << slot;
    }
    let lacking = (0..3).any(|k| taken & (1 << k) == 0 && stated.get(k) != Some(&0.0));
    if lacking {
        return Err(Error::BadArgument);
    }
    Ok(positions)
}

/// `TABLE ROT` at a pose with a free axis (`c`, chosen with the free axis kept): the first
/// rotary table from the workpiece whose turn leaves the tool direction where it is takes
/// the rotation about the tool that `c` leaves to the frame, so that the machine makes the
/// whole rotation \[doc: "position the rotary table to the defined tilting angle";
/// TNC7: the free rotary axis is parallel to the tool and the first in the chain from the
/// workpiece\]; placed as a stated position is (whole turns toward `current`, the travel,
/// the Hirth grid). `c` itself where no table is free (a head axis: the coordinate system
/// turns). Which way the table turns follows from the machine: the turn that reaches
/// `target`.
fn table_turned(
    machine: &Machine,
    target: &crate::Matrix,
    c: Choice,
    current: [f64; 3],
) -> Result<Choice, Error> {
    let r = c.remaining;
    let psi = crate::math::atan2_deg(r[1][0], r[0][0]);
    // Nothing left to the frame (three axes at a pole make the whole rotation): as chosen.
    if crate::math::abs(psi) <= 1e-12 {
        return Ok(c);
    }
    let axes = machine.axes();
    for (k, axis) in axes.iter().enumerate().rev() {
        if axis.side != crate::kinematics::Side::Work {
            continue;
        }
        for sign in [1.0, -1.0] {
            let mut turned = c.axes;
            if let Some(x) = turned.get_mut(k) {
                *x += sign * psi;
            }
            // The whole rotation verified as the solver verifies its solutions (NaN
            // skips the candidate).
            if machine.misses(&turned, target, MAX_AXES) <= VERIFY {
                return machine.commanded(turned, current);
            }
        }
    }
    Ok(c)
}

/// Heidenhain's `SEQ±` on the choice `c` made under it (axis `k`, the `higher` side): the
/// side it names or the control's error — "If the solution you have selected with SYM (SEQ)
/// is not within the machine's range of traverse, then the control displays the Entered
/// angle not permitted error message" (TNC7 user's manual) \[doc\]: [`Error::OutOfTravel`]
/// where the choice fell back to the other solution; and the positions as the angles
/// themselves in (−180°, 180°], not wound toward the current ones — SEQ+ for A+45, C+90 from
/// C−105 and from C−135 gives C+90 (iTNC 530 user's manual, its table of `SEQ` results)
/// \[doc\] — where that angle lies within the axis' travel (else the turn the choice took).
/// At a pole (a free axis) the choice as it is. Not inlined: its solutions are on
/// the stack only after the choice's (stack bound).
#[inline(never)]
fn heidenhain_seq(
    machine: &Machine,
    target: &crate::Matrix,
    c: &mut Choice,
    k: usize,
    higher: bool,
) -> Result<(), Error> {
    use crate::math::{abs, wrap_deg};
    // At a pole a free axis stays where it is: no side to check, no angle to place.
    if c.free {
        return Ok(());
    }
    let all = machine.inverse(target)?;
    let sides = all
        .as_slice()
        .iter()
        .filter_map(|s| s.get(k))
        .map(|&x| wrap_deg(x));
    let side = if higher {
        sides.fold(f64::NEG_INFINITY, f64::max)
    } else {
        sides.fold(f64::INFINITY, f64::min)
    };
    let at = c.axes.get(k).map_or(0.0, |&x| wrap_deg(x));
    // The Hirth grid may move the position by up to half a tooth.
    let tooth = machine
        .axes()
        .get(k)
        .and_then(|a| a.hirth)
        .map_or(0.0, |h| h.step / 2.0);
    // Written so that NaN refuses.
    let near = |a: f64, b: f64| abs(wrap_deg(a - b)) <= tooth + 1e-6;
    if !near(at, side) {
        return Err(Error::OutOfTravel);
    }
    for (x, a) in c.axes.iter_mut().zip(machine.axes().iter()) {
        let plain = wrap_deg(*x);
        if a.limits.map_or(true, |[lo, hi]| plain >= lo && plain <= hi) {
            *x = plain;
        }
    }
    Ok(())
}

/// The axis Fanuc's `G53.1` moves the least first ([`Rule::MasterFirst`]), and the one
/// whose direction of travel `G53.1 P1`/`P2` name (LinuxCNC's primary): on a machine whose
/// axes all turn the tool or all the workpiece the first rotation axis (the master, which
/// carries the other: the first added), on a mixed machine the table's (the first that
/// turns the workpiece) \[doc: Fanuc's output judgement conditions\].
fn fanuc_master(machine: &Machine) -> usize {
    use crate::kinematics::Side;
    let axes = machine.axes();
    let mixed =
        axes.iter().any(|a| a.side == Side::Tool) && axes.iter().any(|a| a.side == Side::Work);
    if mixed {
        axes.iter().position(|a| a.side == Side::Work).unwrap_or(0)
    } else {
        0
    }
}

/// The letter a program names a rotary axis turning about `direction` by: 0 for `A`, 1 for
/// `B`, 2 for `C`, the coordinate axis the direction is nearest (its largest component, the
/// first of equal ones) \[choice: a machine description carries no axis names\]. The
/// direct modes' letters and the five-axis programs' rotary words go to the machine's axes
/// by it.
///
/// ```
/// use cncrot::dialects::program::axis_letter;
/// assert_eq!(axis_letter([0.0, 0.0, -1.0]), 2); // C
/// assert_eq!(axis_letter([0.7, 0.7, 0.1]), 0); // A: equal components, the first
/// ```
pub fn axis_letter(direction: crate::Vector) -> usize {
    let [x, y, z] = direction.map(crate::math::abs);
    if x >= y && x >= z {
        0
    } else if y >= z {
        1
    } else {
        2
    }
}

/// The letters of `machine`'s rotary axes, in the order they were added (0 for `A`, 1 for
/// `B`, 2 for `C`; entries beyond its axes 0): each axis the letter its direction is nearest
/// ([`axis_letter`]); where two are nearest the same letter, the axis more nearly along it
/// keeps it (the first of equals) and the other takes its next nearest letter no axis has
/// \[choice: a nutating head measured at (0, −1, 1.0001) on a C table is the B axis it is
/// called, not a second C\].
///
/// ```
/// use cncrot::dialects::program::axis_letters;
/// use cncrot::kinematics::{Machine, RotaryAxis, Side};
/// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
///     .with_axis(RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [0.0; 3])).unwrap()
///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, -1.0, 1.0001], [0.0; 3])).unwrap();
/// assert_eq!(axis_letters(&m), [2, 1, 0]); // C, B
/// ```
pub fn axis_letters(machine: &Machine) -> [usize; 3] {
    let axes = machine.axes();
    let strength = |k: usize| {
        axes.get(k).map_or(0.0, |a| {
            a.direction
                .iter()
                .fold(0.0f64, |m, x| m.max(crate::math::abs(*x)))
        })
    };
    // The axes most nearly along a coordinate axis choose first (the first of equals).
    let mut order = [0usize, 1, 2];
    for i in 1..3 {
        let mut j = i;
        while j > 0 && strength(order[j]) > strength(order[j - 1]) {
            order.swap(j, j - 1);
            j -= 1;
        }
    }
    let mut letters = [0usize; 3];
    let mut taken = [false; 3];
    for &k in &order {
        let Some(a) = axes.get(k) else {
            continue;
        };
        let c = a.direction.map(crate::math::abs);
        // The letters by nearness: the largest component first, the first of equals.
        let mut rank = [0usize, 1, 2];
        for i in 1..3 {
            let mut j = i;
            while j > 0 && c[rank[j]] > c[rank[j - 1]] {
                rank.swap(j, j - 1);
                j -= 1;
            }
        }
        if let Some(&l) = rank.iter().find(|&&l| !taken[l]) {
            letters[k] = l;
            taken[l] = true;
        }
    }
    letters
}

/// The axis a block's choice words refer to when they name none (Heidenhain's master axis,
/// CYCLE800's direction reference), 0-based: for a head the rotary axis nearest the tool
/// (the last that turns the tool), else the axis nearest the machine base (the first)
/// \[choice: Heidenhain's "first rotary axis from the tool, or from the table"; a machine's
/// own direction reference is commissioning data the description does not carry\].
///
/// ```
/// use cncrot::dialects::program::master_axis;
/// use cncrot::kinematics::{Machine, RotaryAxis, Side};
/// // A head C carrying B: B, the axis nearest the tool.
/// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3])).unwrap()
///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3])).unwrap();
/// assert_eq!(master_axis(&m), 1);
/// ```
pub fn master_axis(machine: &Machine) -> usize {
    let axes = machine.axes();
    axes.iter()
        .rposition(|a| a.side == crate::kinematics::Side::Tool)
        .unwrap_or(0)
}

/// Writes the block that programs `frame` in `dialect` with the command `form` into `out`
/// and returns its length and whether the decomposition was singular (the free angle then
/// sits where the dialect's rule puts it). `decimals < 0` writes the shortest numbers that
/// read back exactly; otherwise every number is rounded to that many decimals (at most
/// 17; `PLANE VECTOR`'s and `PLANE POINTS`' words to at least 7).
///
/// The forms, as written (upper or lower case, single spaces):
///
/// | dialect | forms |
/// |---|---|
/// | SINUMERIK | `CYCLE800` (`_MODE` 57), `CYCLE800 <_MODE>`, `ROT` (RPY), `ROT EULER` |
/// | Heidenhain | `PLANE SPATIAL`, `PLANE EULER`, `PLANE VECTOR`, `PLANE POINTS`, `PLANE PROJECTED` |
/// | Fanuc | `G68.2` |
/// | Syntec | `G158` (`P10157`), `G158 P<p>`, `G68.2` |
/// | TwinCAT | `ROT` |
/// | Haas | `G268` (`Q123`), `G268 Q<q>` |
///
/// Refused: an unknown form ([`Error::BadArgument`]), a frame with an origin for a form
/// without origin words ([`Error::HasOrigin`]), a frame the form cannot express
/// ([`Error::OutOfRange`]), numbers outside what can be written, or a line longer than the
/// dialect reads ([`Error::OutOfRange`], whatever the buffer), a buffer shorter than the
/// line that [`Dialect::max_line`] would hold ([`Error::NoRoom`]).
///
/// ```
/// use cncrot::dialects::program::{write_line, Dialect};
/// use cncrot::{Frame, elementary, Axis};
/// let f = Frame::from_rotation(elementary(Axis::X, 30.0));
/// let mut buf = [0u8; 128];
/// let (n, _) = write_line(Dialect::Heidenhain, b"PLANE SPATIAL", &f, 6, &mut buf).unwrap();
/// assert_eq!(&buf[..n], b"PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY");
/// // The shortest exact numbers show the decomposition's last bit.
/// let (n, _) = write_line(Dialect::Heidenhain, b"PLANE SPATIAL", &f, -1, &mut buf).unwrap();
/// assert_eq!(&buf[..n], b"PLANE SPATIAL SPA+30.000000000000004 SPB+0 SPC+0 STAY");
/// ```
pub fn write_line(
    dialect: Dialect,
    form_text: &[u8],
    frame: &Frame,
    decimals: i32,
    buf: &mut [u8],
) -> Result<(usize, bool), Error> {
    let spec = dialect.parse_form(form_text)?;
    if decimals > crate::text::number::MAX_DECIMALS {
        return Err(Error::BadArgument);
    }
    // A buffer that holds the dialect's longest line and still overflowed holds a line the
    // dialect cannot read: no buffer would help.
    let room = buf.len();
    let mut out = Out::new(buf);
    // A `CYCLE800` written alone swivels, as CYCLE800 programs do (`_DIR` -1; 0 would only
    // calculate the frame) [choice], and no frame is its cancel `CYCLE800()`; a `PLANE`
    // alone stays (`STAY`), as the manuals write it.
    let how = Motion {
        positioning: if dialect == Dialect::Sinumerik && *frame != Frame::IDENTITY {
            Positioning::Turn
        } else {
            Positioning::Stay
        },
        ..Motion::default()
    };
    // One line: an origin the form has no words for is refused, not written as the datum
    // shift before it (which a program's change writes: `write_change`).
    if shift_and_rotation(dialect, &spec, frame) {
        return Err(origin_refused(&spec, frame));
    }
    let singular = tilt_block(dialect, &spec, frame, how, decimals, &mut out)?;
    let len = match out.finish() {
        Some(len) => len,
        None if room >= dialect.max_line() => return Err(Error::OutOfRange),
        None => return Err(Error::NoRoom),
    };
    if len > dialect.max_line() {
        return Err(Error::OutOfRange);
    }
    Ok((len, singular))
}

/// The block of `spec` for `frame` (its cancel for the identity) with the words of `how`
/// the block has; whether the decomposition was singular. Not inlined: a change writes a datum
/// shift and a tilt one after the other, and their numbers' frames need not add up.
#[inline(never)]
fn tilt_block(
    dialect: Dialect,
    spec: &FormSpec,
    frame: &Frame,
    how: Motion,
    decimals: i32,
    out: &mut Out,
) -> Result<bool, Error> {
    // A form without origin words in a dialect of one frame (SINUMERIK's `ROT`): the origin
    // set by the shift command, which replaces the frame (`TRANS X=… Y=… Z=…`), then the
    // rotation added about it by the form's additive command (`AROT`), as programs write a
    // rotated frame with an origin [doc: `AROT` applies on the right of the active frame].
    let moved = shift_and_rotation(dialect, spec, frame);
    let origin = frame.translation;
    let rotation_only = Frame::from_rotation(frame.rotation);
    let (frame, how) = if moved {
        let how = Motion {
            relative: true,
            ..how
        };
        (&rotation_only, how)
    } else {
        (frame, how)
    };
    // The words first: a form that cannot be written (a direct mode) is refused even for
    // the identity.
    let n = spec.form.count();
    let mut words = [0.0; MAX_VALUES];
    let slots = words.get_mut(..n).ok_or(Error::BadArgument)?;
    let singular = form::form_values(spec.form, spec.selector, frame, slots)?;
    let words = words.get(..n).ok_or(Error::BadArgument)?;
    if moved {
        dialect.write_shift(origin, decimals, out)?;
        out.byte(b'\n');
    }
    // Nothing active is written as the cancel, as a program cancels a tilt: `PLANE RESET`
    // becomes `G69`, not a `G68.2` of zeros (which would leave the control in G68.2 mode) —
    // unless the axes turn to the untilted plane, which only the zero tilt and its turn say
    // where the cancel cannot (`write_cancel`).
    if *frame == Frame::IDENTITY && dialect.write_cancel(spec, how, decimals, out)? {
        // A cancel has no angles whose decomposition could be singular.
        return Ok(false);
    }
    dialect.write_line(spec, words, how, decimals, out)?;
    // The untilted plane's words are all zero, whatever the form's singularity.
    Ok(singular && *frame != Frame::IDENTITY)
}

/// Whether [`tilt_block`] writes `frame` as the datum shift and the rotation added about it:
/// a form without origin words in a dialect of one frame with an additive form (SINUMERIK's
/// `ROT`: `TRANS X=… Y=… Z=…`, then `AROT`).
fn shift_and_rotation(dialect: Dialect, spec: &FormSpec, frame: &Frame) -> bool {
    !dialect.keeps_shift()
        && !spec.form.has_origin()
        && frame.translation != [0.0; 3]
        && frame.rotation != crate::IDENTITY
        && dialect
            .relative_form(spec)
            .is_some_and(|r| r.form == spec.form)
}

/// The refusal of [`write_line`] for such a frame: the form's own checks in their order
/// (finite, a rotation…), then [`Error::HasOrigin`]. Not inlined (stack bound).
#[inline(never)]
fn origin_refused(spec: &FormSpec, frame: &Frame) -> Error {
    let mut words = [0.0; MAX_VALUES];
    let slots = words.get_mut(..spec.form.count()).unwrap_or(&mut []);
    match form::form_values(spec.form, spec.selector, frame, slots) {
        Err(e) => e,
        Ok(_) => Error::HasOrigin,
    }
}

/// The longest text [`write_change`] writes: a cancel, a datum shift of up to four blocks
/// and a tilt, each no longer than the dialect reads, with their line ends (a dialect with
/// one frame writes up to three: the shift's reset or the tilt's cancel, and its block, which
/// a form without origin words writes as the shift and the rotation added about it).
pub const MAX_CHANGE: usize = 2048;
const _: () = {
    let mut k = 0;
    while k < Dialect::ALL.len() {
        let d = Dialect::ALL[k];
        // One frame: the shift's reset or the tilt's cancel, then the tilt, which a form
        // without origin words writes as the shift and the rotation added about it.
        let blocks = if d.keeps_shift() { 6 } else { 3 };
        assert!(blocks * d.max_line() + blocks - 1 <= MAX_CHANGE);
        k += 1;
    }
};

/// How a program in `dialect` written with the tilt command `form` holds a state: the datum
/// shift it writes with the dialect's own command, and the tilt (about that datum).
fn split(dialect: Dialect, spec: &FormSpec, p: &Program) -> (Vector, Frame) {
    let f = p.frame;
    let rotation_only = Frame::from_rotation(f.rotation);
    // A direct mode is written in the dialect's direct block, whatever `spec` is for frames,
    // with that block's origin words (Syntec's `G158`, `CYCLE800`) or none (`PLANE AXIAL`).
    let origin_words = match p.direct {
        Some(_) => dialect.direct_has_origin(),
        None => spec.form.has_origin(),
    };
    let untilted = f.rotation == crate::IDENTITY && p.direct.is_none();
    if untilted || (dialect.keeps_shift() && !origin_words) {
        // The whole origin is a datum shift: a form without origin words tilts about it.
        (f.translation, rotation_only)
    } else if dialect.keeps_shift() {
        // Not through `modal()`: a whole state in this frame for three numbers (stack bound).
        (p.shift, super::family::tilt_of(&f, p.shift))
    } else {
        // One frame holds everything: the tilt block writes it whole.
        ([0.0; 3], f)
    }
}

/// Writes the blocks that take a program in `dialect` from the state `before` to the state
/// `after` (both as read by [`Program::line`], in any dialect), with the tilt command `form`
/// (the names of [`write_line`]), one block per line, separated by `\n`, into `buf`; returns
/// the length (0: nothing changes) and whether the tilt's decomposition was singular. What
/// a program translator writes for each block that concerns the frame (no writer says a
/// working plane: a block that only selects one writes nothing and is kept as it stands):
///
/// - A changed datum shift is written with the dialect's own command: Heidenhain's cycle 7
///   (`CYCL DEF 7.0 DATUM SHIFT`, `7.1 X…`, `7.2 Y…`, `7.3 Z…`), Fanuc, Haas and Syntec
///   `G52 X… Y… Z…`, TwinCAT `G58 X… Y… Z…`, after cancelling an active tilt (a shift is
///   programmed untilted); SINUMERIK's `TRANS X=… Y=… Z=…` (`TRANS` alone for none) when no
///   rotation is active.
/// - A form without origin words (every `PLANE`, `ROT`) tilts about the datum: the tilt's
///   origin goes into the datum shift (Heidenhain, TwinCAT); where one frame holds both
///   (SINUMERIK `ROT`) the tilt is written as the shift that replaces the frame and the
///   rotation added about it (`TRANS X=… Y=… Z=…`, then `AROT`).
/// - A changed tilt, or the same tilt with other choice words, is written as [`write_line`]
///   writes it, with the choice words the block has: Heidenhain `SEQ-`/`SEQ+`, CYCLE800
///   `_DIR` −1/+1 where it swivels (−1 also for no choice: a swivel names one \[choice\]); the
///   others have none on the block. A choice of an axis other than the master axis cannot be
///   written ([`Error::NotAvailable`]). Nothing active is written as the cancel; nothing
///   active with the axes turning to the untilted plane as the dialect says that turn
///   (`PLANE RESET TURN FMAX`, a `G68.2` of zeros and `G53.1`, a `CYCLE800` of zero
///   angles), or its cancel where it cannot.
/// - How the machine moves to the plane ([`Program::positioning`]) goes where the dialect
///   says it: Heidenhain's `STAY`, `TURN FMAX`, `MOVE FMAX` in the `PLANE` (a new way of
///   moving to the same plane is the `PLANE` again); Fanuc-style `G53.1`/`G53.6` and Haas
///   `G253` as a block after the tilt, or alone when only the way of moving changed.
///   CYCLE800's `_DIR` 0 where the axes stay (the frame alone), ±1 where they turn;
///   `ROT`, TwinCAT and `G158` say nothing.
///
/// Refused as by [`write_line`], and: a state [`Program::check`] refuses
/// ([`Error::NotFinite`], [`Error::BadArgument`], [`Error::NotARotation`]); [`Error::NoRoom`]
/// only for a buffer shorter than [`MAX_CHANGE`].
///
/// ```
/// use cncrot::dialects::program::{write_change, Dialect, Program};
/// let p0 = Program::default();
/// let (p1, _) = p0.line(Dialect::Fanuc, b"G52 X10 Y20").unwrap();
/// let (p2, _) = p1.line(Dialect::Fanuc, b"G68.2 X0 Y0 Z0 I0 J30 K0").unwrap();
/// let mut buf = [0u8; 2048];
/// let mut heidenhain = |a: &Program, b: &Program| {
///     let (n, _) = write_change(Dialect::Heidenhain, b"PLANE SPATIAL", a, b, 4, &mut buf).unwrap();
///     String::from_utf8(buf[..n].to_vec()).unwrap()
/// };
/// assert_eq!(
///     heidenhain(&p0, &p1),
///     "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+10\nCYCL DEF 7.2 Y+20\nCYCL DEF 7.3 Z+0"
/// );
/// assert_eq!(heidenhain(&p1, &p2), "PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY");
/// assert_eq!(heidenhain(&p2, &p2), "");
/// ```
pub fn write_change(
    dialect: Dialect,
    form_text: &[u8],
    before: &Program,
    after: &Program,
    decimals: i32,
    buf: &mut [u8],
) -> Result<(usize, bool), Error> {
    let spec = dialect.parse_form(form_text)?;
    let c = Change {
        before,
        after,
        step: None,
    };
    write_change_with(dialect, &spec, &c, decimals, buf)
}

/// [`write_change`] with the form already read (the C boundary reads the caller's form
/// name before it touches the output, which may be the same memory), and the increment the
/// block added to the tilt where it is known exactly ([`added_step`]).
pub(crate) fn write_change_with(
    dialect: Dialect,
    spec: &FormSpec,
    c: &Change,
    decimals: i32,
    buf: &mut [u8],
) -> Result<(usize, bool), Error> {
    let room = buf.len();
    let mut out = Out::new(buf);
    let singular = blocks(dialect, spec, c, decimals, &mut out)?;
    let len = match out.finish() {
        Some(len) => len,
        None if room >= MAX_CHANGE => return Err(Error::OutOfRange),
        None => return Err(Error::NoRoom),
    };
    if out.longest_line() > dialect.max_line() {
        return Err(Error::OutOfRange);
    }
    Ok((len, singular))
}

/// What [`write_change`] would write, measured without a buffer: its length and whether the
/// decomposition was singular, or its refusal (never [`Error::NoRoom`]). The C boundary
/// measures first and then writes straight into the caller's buffer, which it leaves
/// untouched on a refusal.
///
/// ```
/// use cncrot::dialects::program::{change_length, write_change, Dialect, Program};
/// let p0 = Program::default();
/// let (p1, _) = p0.line(Dialect::Heidenhain, b"PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN").unwrap();
/// // `G68.2 X0. Y0. Z0. I90. J30. K-90.`, then `G53.1` for TURN.
/// let (n, _) = change_length(Dialect::Fanuc, b"G68.2", &p0, &p1, 4).unwrap();
/// assert_eq!(n, 39);
/// let mut buf = [0u8; 2048];
/// assert_eq!(write_change(Dialect::Fanuc, b"G68.2", &p0, &p1, 4, &mut buf), Ok((n, false)));
/// assert_eq!(&buf[..n], b"G68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.1");
/// ```
pub fn change_length(
    dialect: Dialect,
    form_text: &[u8],
    before: &Program,
    after: &Program,
    decimals: i32,
) -> Result<(usize, bool), Error> {
    let spec = dialect.parse_form(form_text)?;
    let c = Change {
        before,
        after,
        step: None,
    };
    change_length_with(dialect, &spec, &c, decimals)
}

/// [`change_length`] with the form already read (and the increment, as
/// [`write_change_with`]).
pub(crate) fn change_length_with(
    dialect: Dialect,
    spec: &FormSpec,
    c: &Change,
    decimals: i32,
) -> Result<(usize, bool), Error> {
    let mut out = Out::counter();
    let singular = blocks(dialect, spec, c, decimals, &mut out)?;
    let len = out.finish().unwrap_or(usize::MAX);
    if len > MAX_CHANGE || out.longest_line() > dialect.max_line() {
        return Err(Error::OutOfRange);
    }
    Ok((len, singular))
}

/// The blocks a translator writes for one block of the source program, `text`, which
/// [`Program::line`] read from `before` to `after` ([`Remark::Applied`]): [`write_change`]
/// from `before` to `after`, and also what the block restates although nothing changes in
/// the state — the control the program runs on may have something active that the state
/// does not know of. A cancel while no tilt is active (the `PLANE RESET STAY`, `G69` or
/// `CYCLE800()` a program opens with) is written as the target's cancel; a datum shift
/// set to the value it already has (`G52 X0 Y0`, `TRANS DATUM RESET`, cycle 7 with zeros)
/// as the target's datum shift. What a block restates is found by reading it once more on
/// a state where the tilt, or the shift, is something else: a block that leaves no tilt
/// there is a cancel, one that changes the shift there sets it. A block that only names a
/// cycle (`CYCL DEF 7.0`) or a tilt repeated unchanged that stays restates nothing: an empty
/// text. A tilt repeated unchanged that turns the axes (the same `CYCLE800`, or `G53.1`
/// again: a tool change's swivel, after the program moved the axes) is written as that turn.
/// A block that keeps the tilt and states no way of moving (a datum shift under a plane
/// that turned the axes) is written as moving nothing: the tilt written again around the
/// shift stays where it is, without the turn or retraction the state keeps.
/// Refused as [`write_change`].
///
/// ```
/// use cncrot::dialects::program::{write_block, write_change, Dialect, Program};
/// let p0 = Program::default();
/// let (p1, _) = p0.line(Dialect::Heidenhain, b"PLANE RESET STAY").unwrap();
/// assert!(!p1.is_active()); // nothing was active, nothing is
/// let mut buf = [0u8; 2048];
/// let (n, _) = write_change(Dialect::Fanuc, b"G68.2", &p0, &p1, 4, &mut buf).unwrap();
/// assert_eq!(n, 0);
/// // The program's safety cancel is kept as the target's cancel.
/// let text = b"PLANE RESET STAY";
/// let (n, _) = write_block(Dialect::Fanuc, b"G68.2", &p0, &p1, text, 4, &mut buf).unwrap();
/// assert_eq!(&buf[..n], b"G69");
/// ```
pub fn write_block(
    dialect: Dialect,
    form_text: &[u8],
    before: &Program,
    after: &Program,
    text: &[u8],
    decimals: i32,
    buf: &mut [u8],
) -> Result<(usize, bool), Error> {
    let spec = dialect.parse_form(form_text)?;
    let (mut from, mut to) = (*before, *after);
    let step = block_states(&mut from, &mut to, text);
    let c = Change {
        before: &from,
        after: &to,
        step: step.as_ref(),
    };
    write_change_with(dialect, &spec, &c, decimals, buf)
}

/// The states [`write_block`] writes the change between, made in place from the states
/// before and after the block `text` (`from`, `to`), and the tilt's step where the block adds
/// to it ([`added_step`]): what the block restates ([`restate`]); a block that turns the axes
/// to the plane the state says they are at (a tool change's swivel again, after the program
/// moved them: the same `CYCLE800`, `G68.2` and `G53.1` again) from a state that stays, so
/// that the turn is written; a block that moves no rotary axis (a datum shift under a plane
/// that turned) to a state that stays, so that the tilt written again around it does not
/// turn or retract again. The C boundary's `cncrot_program_write_block` writes the same.
pub(crate) fn block_states(from: &mut Program, to: &mut Program, text: &[u8]) -> Option<Frame> {
    restate(from, to, text);
    let step = added_step(from, to, text);
    match stated_motion(from, to, text) {
        Some(true) if from.positioning != Positioning::Stay => *from = from.staying(),
        Some(false) => *to = to.staying(),
        _ => {}
    }
    step
}

/// Whether the block `text`, read from `from` to `after` with the tilt the same and a way of
/// moving after it (`TURN`, `G53.1`), states that way itself: read on a state that stays,
/// it moves (`Some(true)`: the same `CYCLE800` or `G53.1` again, which turns the axes again
/// wherever the program moved them) or it stays (`Some(false)`: a datum shift under
/// `PLANE … TURN` — cycle 7's lines, `TRANS DATUM`, `G52` — whose tilt written again around
/// it must not turn or retract again, where the control moves nothing). `None`: another
/// tilt, no way of moving, a block that changes nothing (`CYCL DEF 19.0`), or a state
/// untilted after it (no tilt to write again). Not inlined, like [`leaves_untilted`]
/// (stack bound).
#[inline(never)]
fn stated_motion(from: &Program, after: &Program, text: &[u8]) -> Option<bool> {
    let dialect = after.dialect?;
    let same_tilt = (from.frame.rotation, from.direct) == (after.frame.rotation, after.direct);
    if !same_tilt || after.positioning == Positioning::Stay {
        return None;
    }
    let still = of_no_dialect(from).staying();
    match still.line(dialect, text) {
        Ok((q, Remark::Applied)) if q.positioning != Positioning::Stay => Some(true),
        // A block that changed nothing and restates nothing (`CYCL DEF 19.0`, which only
        // names the cycle) writes nothing: written as staying, the tilt came out again.
        // Untilted (the axes turned home by a zero tilt), no tilt is written again around a
        // datum shift: nothing to keep from turning.
        Ok((_, Remark::Applied)) if from != after && !untilted(after) => Some(false),
        _ => None,
    }
}

/// The words of a block of a `dialect` program that are not the frame's, as they stand:
/// what a translator keeps beside the blocks [`write_block`] writes for it (the motion,
/// feed, compensation and mode words an ISO-style post writes on the block of a tilt or a
/// cancel, and the block number), written to `buf`. Without them a translation drops a
/// retract (`G91 G28 Z0.` of `G91 G28 Z0. G69`) or a feed (`N40 G1 F300.` of
/// `N40 G1 G68.2 … F300.`). Empty where nothing but the block number and comments is left,
/// and in the dialects whose readers refuse other words beside a frame command (SINUMERIK,
/// TwinCAT). A block that holds no frame command is left whole (up to a NUL byte, which
/// ends it as it ends a C string). Heidenhain's: the M functions of the turn to the plane
/// (`M3` of `L B+Q121 C+Q122 R0 FMAX M3`, switched at the block's start; not `M126`/`M127`,
/// the rotary axes' way, which no other control writes) or of a block of M functions alone.
///
/// Errors: [`Error::LineTooLong`] (a text longer than the dialect reads, with a line end),
/// [`Error::NoRoom`] (`buf` too small: the text's length always suffices).
///
/// ```
/// use cncrot::dialects::program::{rest, Dialect};
/// let mut buf = [0u8; 256];
/// let n = rest(Dialect::Fanuc, b"G91 G28 Z0. G69", &mut buf).unwrap();
/// assert_eq!(&buf[..n], b"G91 G28 Z0.");
/// let n = rest(Dialect::Fanuc, b"N40 G1 G68.2 X0. Y0. Z0. I0. J30. K0. F300.", &mut buf).unwrap();
/// assert_eq!(&buf[..n], b"N40 G1 F300.");
/// assert_eq!(rest(Dialect::Fanuc, b"N50 G69 (CANCEL)", &mut buf), Ok(0));
/// ```
pub fn rest(dialect: Dialect, text: &[u8], buf: &mut [u8]) -> Result<usize, Error> {
    // The block without its line end, as `Program::line` measures it.
    let text = block_of(dialect, text).map_err(|e| e.error)?;
    // A NUL byte ends the text, as it ends the C string the rest is written as.
    let text = text.split(|&b| b == 0).next().unwrap_or(&[]);
    let mut out = Out::new(buf);
    if !dialect.rest(text, &mut out) {
        return Ok(0);
    }
    out.finish().ok_or(Error::NoRoom)
}

/// Whether a translator writes two blocks read one after the other — the first from
/// `before` to `after`, the next from `after` to `next` — as one change, from `before` to
/// `next` at the second block (the first writes nothing): they are one command spread over
/// lines, which the target says in one.
///
/// - The lines of one datum shift: each changes the shift alone, or nothing (Heidenhain's
///   `CYCL DEF 7.1 X…`, `7.2 Y…`, `7.3 Z…`, an axis restated; a target writes the whole
///   shift once, instead of one shift per axis, or under a tilt one cancel and tilt again
///   per axis). A first line that changes nothing joins only while a tilt is active: with
///   none, it may be a cancel the program restates (see [`write_block`]), which must stay.
///   What a second line restates stays: [`write_block`] reads it on the joined change.
/// - A tilt and the block that turns the axes to it: the next block changes only how the
///   machine moves (`G68.2` then `G53.1`, `PLANE … STAY` then `L A+Q120 C+Q122 … FMAX`, `G268`
///   then `G253`), after a first that changed something and did not turn: one `PLANE … TURN`
///   or `CYCLE800`.
///
/// Within one dialect a translator keeps the blocks as they stand and needs no join.
///
/// ```
/// use cncrot::dialects::program::{joins, Dialect, Program};
/// let read = |p: &Program, l: &str| p.line(Dialect::Heidenhain, l.as_bytes()).unwrap().0;
/// let p0 = read(&Program::default(), "CYCL DEF 7.0 DATUM SHIFT");
/// let p1 = read(&p0, "CYCL DEF 7.1 X+10");
/// let p2 = read(&p1, "CYCL DEF 7.2 Y+20");
/// let p3 = read(&p2, "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY");
/// let p4 = read(&p3, "L A+Q120 B+Q121 C+Q122 R0 FMAX");
/// assert!(joins(&p0, &p1, &p2)); // one G52 X10. Y20. Z0.
/// assert!(!joins(&p1, &p2, &p3)); // the shift, then the tilt
/// assert!(joins(&p2, &p3, &p4)); // one G68.2 … then G53.1, one PLANE … TURN
/// // Without the cycle's first line, from a program's first block: the same.
/// let q1 = read(&Program::default(), "CYCL DEF 7.1 X+10");
/// assert!(joins(&Program::default(), &q1, &read(&q1, "CYCL DEF 7.2 Y+20")));
/// ```
pub fn joins(before: &Program, after: &Program, next: &Program) -> bool {
    // Everything but the shift (and the frame's origin, which holds it) the same.
    let shift_only = |a: &Program, b: &Program| {
        a.frame.rotation == b.frame.rotation
            && Program {
                shift: b.shift,
                frame: b.frame,
                // The dialect is recorded by the first block read.
                dialect: b.dialect,
                ..*a
            } == *b
    };
    // Everything but how the machine moves to the plane the same.
    let moving_only = |a: &Program, b: &Program| {
        Program {
            choice: b.choice,
            positioning: b.positioning,
            retract: b.retract,
            retract_mm: b.retract_mm,
            feed: b.feed,
            feed_mm_min: b.feed_mm_min,
            table_rot: b.table_rot,
            dialect: b.dialect,
            ..*a
        } == *b
    };
    let tilted = after.frame.rotation != crate::IDENTITY || after.direct.is_some();
    // Whether the block changed the state (the dialect recorded by a first block is no
    // change: a safety cancel first in a program is a block of its own).
    let changed = Program {
        dialect: after.dialect,
        ..*before
    } != *after;
    let shifts = shift_only(before, after) && shift_only(after, next) && (changed || tilted);
    let turns = changed
        && after.positioning == Positioning::Stay
        && next.positioning != Positioning::Stay
        && moving_only(after, next);
    shifts || turns
}

/// Turns `from` (the state before the block) into the state [`write_block`] writes the
/// change from: with a tilt when `text` is a cancel and none was active, with another shift
/// when `text` sets the shift to the value it had. Left as it is when the block changed
/// what it restates, or `after` has no dialect. The changed state is of no dialect, which
/// passes [`Program::check`] whatever the program's dialect (no programmed angles, no direct
/// mode).
fn restate(from: &mut Program, after: &Program, text: &[u8]) {
    let Some(dialect) = after.dialect else {
        return;
    };
    let cancel = untilted(from) && untilted(after) && leaves_untilted(from, dialect, text);
    // A direct mode's positions are no frame to shift under (its state is written again
    // whole): left as it is.
    let shift =
        from.shift == after.shift && from.direct.is_none() && sets_shift(from, dialect, text);
    if cancel {
        from.frame = Frame {
            rotation: PROBE_TILT,
            translation: from.shift,
        };
    }
    if shift {
        from.shift = other_shift(from.shift);
        from.frame.translation = other_shift(from.frame.translation);
    }
    if cancel || shift {
        *from = of_no_dialect(from);
    }
}

/// `p` as a state of no dialect: no programmed angles, no direct mode, no `TABLE ROT`, so
/// that it passes [`Program::check`] with any frame (the probes of [`restate`]).
fn of_no_dialect(p: &Program) -> Program {
    Program {
        dialect: None,
        angles: [0.0; 3],
        direct: None,
        table_rot: false,
        ..*p
    }
}

/// Any tilt will do: a cancel leaves none.
const PROBE_TILT: crate::Matrix = {
    let (s, c) = (0.5, 0.866_025_403_784_438_6);
    [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]
};

/// Another shift than `v`.
fn other_shift(v: Vector) -> Vector {
    v.map(|x| x + 1.0)
}

/// No tilt, no direct mode: the frame is the datum shift alone.
fn untilted(p: &Program) -> bool {
    p.direct.is_none() && p.frame.rotation == crate::IDENTITY && p.frame.translation == p.shift
}

/// Whether `text` leaves no tilt when read on `before` with a tilt. Not inlined, like
/// [`sets_shift`]: each probe's state and its result are on the stack only while it reads.
#[inline(never)]
fn leaves_untilted(before: &Program, dialect: Dialect, text: &[u8]) -> bool {
    let tilted = Program {
        frame: Frame {
            rotation: PROBE_TILT,
            translation: before.shift,
        },
        ..of_no_dialect(before)
    };
    matches!(tilted.line(dialect, text), Ok((p, Remark::Applied)) if untilted(&p))
}

/// Whether `text` changes the shift when read on `before` with another shift.
#[inline(never)]
fn sets_shift(before: &Program, dialect: Dialect, text: &[u8]) -> bool {
    let shifted = Program {
        frame: Frame {
            rotation: before.frame.rotation,
            translation: other_shift(before.frame.translation),
        },
        shift: other_shift(before.shift),
        ..of_no_dialect(before)
    };
    matches!(shifted.line(dialect, text), Ok((p, Remark::Applied)) if p.shift != shifted.shift)
}

/// The blocks of [`write_change`] into `out`: the increment where the tilt was added to
/// ([`added`]), else the whole change ([`change`]); whether the decomposition was singular.
#[inline(never)]
fn blocks(
    dialect: Dialect,
    spec: &FormSpec,
    c: &Change,
    decimals: i32,
    out: &mut Out,
) -> Result<bool, Error> {
    match added(dialect, spec, c, decimals, out) {
        Some(r) => r,
        None => change(dialect, spec, c.before, c.after, decimals, out),
    }
}

/// A change to write: the states before and after it, and the increment the block added to
/// the tilt where its reader gave it ([`added_step`]). One argument for three (stack bound).
pub(crate) struct Change<'a> {
    /// The state before the block.
    pub before: &'a Program,
    /// The state after it.
    pub after: &'a Program,
    /// The block's own increment.
    pub step: Option<&'a Frame>,
}

/// The blocks of [`write_change`] into `out` where `after`'s tilt was added to the one before
/// ([`Program::relative`]: `PLANE RELATIV`, `G68.4`, `AROT`, …): the target's incremental
/// form (`G68.4`, `PLANE RELATIV` one angle per block, `CYCLE800` with `_ST` 1, `AROT`,
/// `G158 P01…`) with the increment — `step` where the block's reader gave it
/// ([`added_step`]: the words' own numbers), else `before⁻¹·after` —, then the block that moves the machine
/// where the dialect has one, so that a loop which repeats the source block repeats the
/// target's and adds as often; the same plane with another way of moving, where the tilt
/// block says it, as a zero increment (`PLANE RELATIV SPA+0 TURN FMAX`). `None` where the
/// change is written whole ([`change`]): not added to, another datum shift (in the program
/// or as the target writes it) or a direct mode before, a state [`Program::check`]
/// refuses, a target without an incremental form (`G268`, TwinCAT, whose `AROT` adds
/// angles, not rotations), or an increment with an origin the form has no words for
/// (`PLANE RELATIV`, `AROT`). Not inlined: its frame is beside [`change`]'s, not on top of
/// it.
#[inline(never)]
fn added(
    dialect: Dialect,
    spec: &FormSpec,
    &Change {
        before,
        after,
        step,
    }: &Change,
    decimals: i32,
    out: &mut Out,
) -> Option<Result<bool, Error>> {
    if !(decimals <= crate::text::number::MAX_DECIMALS && adds(dialect, spec, before, after)) {
        return None;
    }
    let rspec = dialect.relative_form(spec)?;
    if before.frame == after.frame
        && !(before.motion() != after.motion() && dialect.positioning_in_block())
    {
        return None;
    }
    let how = Motion {
        relative: true,
        ..after.motion()
    };
    let step = increment(&before.frame, &after.frame, step);
    if step.translation != [0.0; 3] && !rspec.form.has_origin() {
        return None;
    }
    let mut words = [0.0; MAX_VALUES];
    let slots = words.get_mut(..rspec.form.count())?;
    Some(
        form::form_values(rspec.form, rspec.selector, &step, slots).and_then(|singular| {
            let n = rspec.form.count();
            dialect.write_line(&rspec, words.get(..n).unwrap_or(&[]), how, decimals, out)?;
            if let Some(text) = dialect.positioning_block(spec, how) {
                out.byte(b'\n');
                out.text(text);
            }
            Ok(singular)
        }),
    )
}

/// Whether `after`'s tilt was added to `before`'s with nothing else changed: both states
/// as a reader leaves them, no direct mode before, the same datum shift in the program and
/// as the target writes it (a `TRANS` before a SINUMERIK `AROT` is the frame's origin, a
/// Fanuc `G52` while no tilt is active). Not inlined: the states it splits are gone when
/// the increment is written (stack bound).
#[inline(never)]
fn adds(dialect: Dialect, spec: &FormSpec, before: &Program, after: &Program) -> bool {
    after.relative
        && before.direct.is_none()
        && before.shift == after.shift
        && before.check().is_ok()
        && after.check().is_ok()
        && split(dialect, spec, before).0 == split(dialect, spec, after).0
}

/// The increment from `before` to `after`: `step` where it leads from one to the other (to
/// 1e-12 of the frames' size; a TwinCAT `AROT` adds angles, which is no increment on the
/// right), else `before⁻¹·after`, its origin 0 where it is within 1e-12 of the frames' size
/// (a rotation added alone: the datum shift added back to the tilt's origin rounds). Not
/// inlined: its products are gone when the increment is written (stack bound).
#[inline(never)]
fn increment(before: &Frame, after: &Frame, step: Option<&Frame>) -> Frame {
    let size = before
        .translation
        .iter()
        .chain(&after.translation)
        .fold(1.0, |m: f64, &x| m.max(crate::math::abs(x)));
    let near = |x: f64, y: f64| crate::math::abs(x - y) <= 1e-12 * size;
    let leads = |s: &Frame| {
        let f = before.compose(s);
        let rows = f
            .rotation
            .iter()
            .flatten()
            .zip(after.rotation.iter().flatten());
        rows.chain(f.translation.iter().zip(&after.translation))
            .all(|(x, y)| near(*x, *y))
    };
    let mut step = match step {
        Some(s) if leads(s) => *s,
        _ => before.inverse().compose(after),
    };
    if step.translation.iter().all(|&x| near(x, 0.0)) {
        step.translation = [0.0; 3];
    }
    step
}

/// The frame the block `text` added to the active tilt as its reader computes it, from the
/// words' own numbers (`PLANE RELATIV SPC+15` is exactly `Rz(15)`, where `before⁻¹·after`
/// carries the rounding of two products): the block read again on a state with nothing
/// active. `None` where `after` was not added to or the block is no such command (the
/// second line of a joined pair). Not inlined: the probe's state is on the stack only while
/// it reads.
#[inline(never)]
fn added_step(before: &Program, after: &Program, text: &[u8]) -> Option<Frame> {
    let dialect = after.dialect.filter(|_| after.relative)?;
    let probe = Program {
        frame: Frame::IDENTITY,
        shift: [0.0; 3],
        relative: false,
        ..of_no_dialect(before)
    };
    match probe.line(dialect, text) {
        Ok((p, Remark::Applied)) if p.relative => Some(p.frame),
        _ => None,
    }
}

/// The whole change of [`write_change`] into `out`; whether the decomposition was singular.
/// Not inlined: measured and then written, its frame is on the stack once.
#[inline(never)]
fn change(
    dialect: Dialect,
    spec: &FormSpec,
    before: &Program,
    after: &Program,
    decimals: i32,
    out: &mut Out,
) -> Result<bool, Error> {
    if decimals > crate::text::number::MAX_DECIMALS {
        return Err(Error::BadArgument);
    }
    before.check()?;
    after.check()?;
    let (s0, mut t0) = split(dialect, spec, before);
    let (s1, t1) = split(dialect, spec, after);
    let mut blocks = 0;
    let mut next = |out: &mut Out| {
        if blocks > 0 {
            out.byte(b'\n');
        }
        blocks += 1;
    };
    let mut singular = false;
    // How the machine moves: built where it is passed (the two copies held across the change
    // cost the export 32 bytes of stack, measured).
    let stay = Motion::default;
    let how = || after.motion();
    // A direct mode's tilt is its positions (its rotation only the machine knows).
    let (mut d0, d1) = (
        before.direct.map(|d| (d, before.angles)),
        after.direct.map(|d| (d, after.angles)),
    );
    let active = t1 != Frame::IDENTITY || d1.is_some();
    // The form turns the axes with a block of its own (`G53.1`, `G253`).
    let turn_block = dialect
        .positioning_block(
            spec,
            Motion {
                positioning: Positioning::Turn,
                ..Motion::default()
            },
        )
        .is_some();
    // A choice of solution is a word of that block where it has one (`G53.1 P1`), not of the
    // tilt block: a new choice alone is that block again, not the tilt.
    let chosen = before.choice != after.choice;
    let words_changed = (chosen && !turn_block)
        || before.table_rot != after.table_rot
        || (before.retract, before.retract_mm.to_bits())
            != (after.retract, after.retract_mm.to_bits())
        || (before.feed, before.feed_mm_min.to_bits()) != (after.feed, after.feed_mm_min.to_bits());
    let moved = before.positioning != after.positioning;
    // Where the tilt block says how to move, a new way of moving is a new tilt block; where a
    // block of its own moves the machine (`G53.1`), no block takes that back: a tilt that
    // stays where it is after one that turned is the tilt block again, without it.
    let unsaid = after.positioning == Positioning::Stay && turn_block;
    let rewrite =
        active && (words_changed || (moved && (dialect.positioning_in_block() || unsaid)));
    // The axes turned to the untilted plane (a zero tilt with `TURN`), or no longer: the
    // zero tilt that turns them, or the cancel after it.
    let zero_turn = |p: &Program| {
        p.frame.rotation == crate::IDENTITY
            && p.direct.is_none()
            && p.positioning != Positioning::Stay
    };
    // Where a block of its own turns the axes, the zero tilt is cancelled after it (below):
    // nothing is left to take back.
    let rewrite = rewrite || (moved && ((zero_turn(before) && !turn_block) || zero_turn(after)));
    let mut tilt_written = false;
    // The axes turned home with the cancel a new datum shift needs first, where the tilt
    // block says how to move (`PLANE RESET TURN MB MAX`, a `CYCLE800` of zeros with `_DIR`):
    // the cancel is that turn, written before the shift; nothing is left to write after it.
    // It was the cancel that stays (`PLANE RESET STAY`, `CYCLE800()`), and the turn was lost.
    let home = !active && zero_turn(after) && dialect.positioning_in_block();
    let cancel_how = || if home { how() } else { stay() };
    let tilt = |out: &mut Out| match d1 {
        Some(d) => dialect
            .write_direct(spec, t1.translation, d, how(), decimals, out)
            .map(|()| false),
        None => tilt_block(dialect, spec, &t1, how(), decimals, out),
    };
    if dialect.keeps_shift() {
        let mut homed = false;
        if s0 != s1 {
            if t0 != Frame::IDENTITY || d0.is_some() {
                next(out);
                tilt_block(dialect, spec, &Frame::IDENTITY, cancel_how(), decimals, out)?;
                (t0, d0, homed) = (Frame::IDENTITY, None, home);
            }
            next(out);
            dialect.write_shift(s1, decimals, out)?;
        }
        let replaced = (t0, d0) != (t1, d1);
        if (replaced || rewrite) && !homed {
            // A new tilt over an active one where a block of its own turns the axes
            // (`G68.2`, `G268`): cancelled first (`G69`, `G269`), which means the same where
            // the control replaces the tilt and is what a control that refuses a tilt in
            // tilt mode needs [choice]. A `PLANE`, a `G158` replace it.
            let over = (t0 != Frame::IDENTITY || d0.is_some()) && (active || zero_turn(after));
            if replaced && over && turn_block {
                next(out);
                tilt_block(dialect, spec, &Frame::IDENTITY, stay(), decimals, out)?;
            }
            next(out);
            singular = tilt(out)?;
            tilt_written = true;
        }
    } else if (s0, t0, d0) != (s1, t1, d1) || rewrite {
        // One frame, which each command replaces whole: a translation alone is the shift
        // command, anything else the tilt block. Written so that the text means the same
        // where the control keeps the tilt apart from the shift (a SINUMERIK whose CYCLE800
        // writes system frames, which `TRANS` leaves alone): a tilt is cancelled by its own
        // cancel before a shift alone is set, and a shift alone is reset (`TRANS`) before a
        // tilt block carries the whole origin [choice].
        let tilted0 = t0 != Frame::IDENTITY || d0.is_some();
        let shifted0 = !tilted0 && s0 != [0.0; 3];
        if t1 == Frame::IDENTITY && d1.is_none() && (s1 != [0.0; 3] || shifted0) {
            // A tilt cancelled, or the axes turned home from no tilt (`PLANE RESET TURN`
            // after a datum shift alone): the cancel, or the zero tilt that turns them, then
            // the shift alone.
            if tilted0 || (home && moved) {
                next(out);
                tilt_block(dialect, spec, &Frame::IDENTITY, cancel_how(), decimals, out)?;
            }
            next(out);
            match dialect.write_shift(s1, decimals, out) {
                Err(Error::NotAvailable) => {
                    let f = Frame::with_translations(s1, crate::IDENTITY, [0.0; 3]);
                    tilt_block(dialect, spec, &f, how(), decimals, out)?;
                }
                r => r?,
            }
        } else {
            // A tilt written as its shift and its rotation (`TRANS X=…`, `AROT`) sets the
            // shift itself.
            let own_shift = d1.is_none() && !spec.form.has_origin() && t1.translation != [0.0; 3];
            if shifted0 && (t1 != Frame::IDENTITY || d1.is_some()) && !own_shift {
                // A dialect with no shift command has had none written.
                let mut reset = Out::counter();
                if dialect.write_shift([0.0; 3], decimals, &mut reset).is_ok() {
                    next(out);
                    dialect.write_shift([0.0; 3], decimals, out)?;
                }
            }
            next(out);
            singular = tilt(out)?;
            tilt_written = true;
        }
    }
    // Where a block of its own moves the machine (`G53.1`): after a new tilt, or alone (a
    // direct mode's block moves the axes itself).
    let rechosen = chosen && turn_block && after.positioning != Positioning::Stay;
    if (active || zero_turn(after)) && d1.is_none() && (tilt_written || moved || rechosen) {
        if let Some(text) = dialect.positioning_block(spec, how()) {
            next(out);
            out.text(text);
            // A zero tilt that turned the axes (`G68.2` of zeros, `G53.1`): cancelled, so that
            // the target is untilted as the state is — a Fanuc refuses `G52` in `G68.2` mode,
            // and the next tilt is written over none [choice].
            if !active {
                next(out);
                tilt_block(dialect, spec, &Frame::IDENTITY, stay(), decimals, out)?;
            }
        }
    }
    Ok(singular)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A line longer than the dialect reads is `OutOfRange` whatever the buffer; `NoRoom`
    /// only when a buffer that cannot hold the dialect's longest line is the reason.
    #[test]
    fn no_room_only_for_the_buffer() {
        let a = 1e-97;
        let m = crate::matrix_from_angles(
            crate::Kind::Intrinsic,
            crate::AxisCode::new(57).unwrap(),
            [a, a, a],
        );
        let f = Frame::with_translations([1e99; 3], m, [0.0; 3]);
        // Nine numbers of about 100 digits: more than any buffer of 512 bytes holds.
        for room in [256, 512, 4096] {
            let mut buf = vec![0x5Au8; room];
            assert_eq!(
                write_line(Dialect::Syntec, b"G158", &f, -1, &mut buf),
                Err(Error::OutOfRange),
                "{room}"
            );
        }
        let mut small = [0u8; 40];
        let g = Frame::from_rotation(m);
        assert_eq!(
            write_line(Dialect::Syntec, b"G158", &g, 4, &mut small),
            Err(Error::NoRoom)
        );
        let mut enough = [0u8; 256];
        assert!(write_line(Dialect::Syntec, b"G158", &g, 4, &mut enough).is_ok());
    }

    #[test]
    fn a_program_speaks_one_dialect() {
        let (p, _) = Program::default()
            .line(Dialect::Fanuc, b"G68.2 J30")
            .unwrap();
        assert_eq!(
            p.line(Dialect::Haas, b"G269").unwrap_err().error,
            Error::BadArgument
        );
        let long = [b' '; 257];
        assert_eq!(
            p.line(Dialect::Fanuc, &long).unwrap_err(),
            LineError {
                error: Error::LineTooLong,
                column: 257,
                expected: None,
            }
        );
    }
}
