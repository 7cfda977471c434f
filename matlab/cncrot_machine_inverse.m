% CNCROT_MACHINE_INVERSE  Every set of rotary-axis positions for an orientation.
%   [S, FREE] = cncrot_machine_inverse(MACHINE, F) gives the K-by-3 positions (degrees,
%   each in (-180, 180], K = 1 or 2) whose tool frame has the orientation of the 4-by-4
%   frame F: the whole rotation with three axes, the tool direction F(1:3,3) with fewer.
%   Travel limits are ignored (see CNCROT_MACHINE_CHOOSE). FREE is true at a singular pose
%   (the target direction along an axis, which is then free: the family once, at 0).
%   MACHINE as in CNCROT_MACHINE_FORWARD. Errors: cncrot:unreachable, ...
%
%   Example:
%     head = [0 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 150 -100 100 0 0 0];
%     S = cncrot_machine_inverse(head, cncrot_machine_forward(head, [30 40 0]));
%     % S = [30 40 0; -150 -40 0] (in some order)
%
%   See also CNCROT_MACHINE_FORWARD, CNCROT_MACHINE_CHOOSE.
