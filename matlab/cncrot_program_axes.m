% CNCROT_PROGRAM_AXES  The rotary-axis positions a program's active tilt moves a machine to.
%   [AXES, STATUS] = cncrot_program_axes(STATE, MACHINE, CURRENT)
%   STATE is the program state from cncrot_program_lines, MACHINE as in
%   CNCROT_MACHINE_FORWARD, CURRENT the current rotary positions (1-by-3, degrees; 0 where
%   the machine has no axis; default zeros). AXES (1-by-3) is the solution the tilt's own
%   choice words pick (SEQ-/SEQ+, _DIR -1/+1: the master axis' lower/higher angle; G53.1
%   P1/P2: it turns only up/down); without them, for a Fanuc tilt Fanuc's rule
%   ('master_first' on its first rotation axis, a mixed machine's table axis), else the
%   solution closest to CURRENT (what cncrot_machine_choose(MACHINE, F, CURRENT, 'closest')
%   gives for the state's frame F, the choice SINUMERIK makes for a frame and Heidenhain
%   makes without SEQ): whole turns unwound toward CURRENT, within the travel limits and on
%   the Hirth grids. Heidenhain's SEQ gives the angles themselves, in (-180, 180], and
%   cncrot:outOfTravel where the side it names lies beyond the travel. No tilt active: the
%   positions of the identity frame. A direct mode (PLANE AXIAL, G158 mode 2, CYCLE800
%   direct): the positions it states, each axis taking its letter's (A about X, B about Y,
%   C about Z, by the axis' direction) or its place's, as stated on an axis with travel
%   limits, the turn nearest CURRENT on a modulo axis. STATUS 0, 2 (a free axis kept at its current position)
%   or 3 (a Hirth axis snapped). Errors: cncrot:unreachable, cncrot:outOfTravel,
%   cncrot:badState (a state whose fields were changed), ...; the message names the argument.
%
%   Example (a head: C about Z carrying B about Y):
%     head = [0 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 150 -100 100 0 0 0];
%     [~, st] = cncrot_program_lines('heidenhain', 'PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY');
%     a = cncrot_program_axes(st, head, [730 0 0])     % [720 30 0]
%
%   See also CNCROT_PROGRAM_LINES, CNCROT_MACHINE_CHOOSE, CNCROT_MACHINE_FORWARD.
