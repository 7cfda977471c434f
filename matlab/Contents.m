% cncrot: CNC rotation conventions, tilted planes, probing and machine kinematics (MEX).
% Version 0.2.0
%
% Conventions
%   cncrot_matrix          - Rotation matrices from angles (degrees).
%   cncrot_angles          - Angles (degrees) of rotation matrices in a convention.
%   cncrot_convert         - Converts angles (degrees) from one convention to another.
%   cycle600               - The paper's cycle CYCLE600 (recalculation of rotations), on the C library.
%
% Tilted-plane commands of the controllers
%   cncrot_form_frame      - Frames (4-by-4) of a controller's tilted-plane command.
%   cncrot_form_values     - The words of a controller's tilted-plane command for given frames.
%   cncrot_forms           - The codes of the dialects' tilted-plane forms, with their selector and words.
%
% Part programs
%   cncrot_program_lines   - What program lines do to the active frame, as the controller does.
%   cncrot_tool_path_lines - A five-axis part program's motion blocks as CL points or machine axes.
%   cncrot_program_write   - The program line that programs a frame in a controller's language.
%   cncrot_program_translate - A part program in another controller's language, block by block.
%   cncrot_program_axes    - The rotary-axis positions a program's active tilt moves a machine to.
%   cncrot_dialects        - The codes of the controller dialects.
%
% Probing
%   cncrot_probe_flange    - The paper's flange probing: the tilt of a flange from four points.
%   cncrot_probe_plane     - The least-squares plane through probed points, and its flatness.
%   cncrot_probe_edge      - The turn about a tilted plane's normal that lays X' along a probed edge.
%
% Machine kinematics
%   cncrot_machine_forward - The tool frame of a machine at rotary-axis positions.
%   cncrot_machine_inverse - Every set of rotary-axis positions for an orientation.
%   cncrot_machine_choose  - The rotary-axis positions to move to for an orientation.
%   cncrot_machine_tcp_forward - Tool tip and direction from every machine axis.
%   cncrot_cl_pose             - The pose of CL points (tool tip and direction).
%   cncrot_machine_tcp_inverse - Every machine axis for tool tips and directions (a path).
%
% Building
%   build_mex              - Builds the MEX functions, in MATLAB or GNU Octave.
%
% Names may stand where numeric codes do (case-insensitive, char or string):
%   conventions 'intrinsic' (1), 'extrinsic' (0);
%   axis sequences 'XYZ' (57), 'ZXY' (39), "ZX'Y''", 'X0Z' (49: '0' skips a rotation);
%   dialects 'sinumerik' 'heidenhain' 'fanuc' 'syntec' 'twincat' 'haas' (1..6);
%   rules 'closest' 'minus' 'plus' 'inverse' 'positive_turn' 'negative_turn' 'master_first' (0..6);
%   forms as cncrot_forms lists them.
% Integers may be of any numeric class or logical. The table: docs/matlab.md.
