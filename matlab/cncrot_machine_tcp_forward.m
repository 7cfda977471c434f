% CNCROT_MACHINE_TCP_FORWARD  Tool tip and direction from every machine axis.
%   P = cncrot_machine_tcp_forward(MACHINE, AXES, L) for AXES N-by-6 — X Y Z (mm, the
%   machine coordinates of the tool adapter's reference point) then the rotary positions
%   (degrees, in the order the axes are described; unused axes 0) — and a tool of length
%   L (mm) gives 4-by-4-by-N poses in workpiece coordinates: P(1:3,4) is the tool tip,
%   P(1:3,3) the tool direction, P(1:3,1:3) the frame of cncrot_machine_forward.
%   MACHINE as for cncrot_machine_forward.
%
%   Example (an AC table: A about X through z = 100, C on it; tool 50 mm):
%     ac = [1 1 0 0 0 0 100 0 0 0 0 0; 1 0 0 1 0 0 0 0 0 0 0 0];
%     P = cncrot_machine_tcp_forward(ac, [0 58.6603 68.3975 30 90 0], 50);
%     % P(1:3,4) = [10; 0; 0], P(1:3,3) = [0.5; 0; 0.866]
%
%   See also CNCROT_MACHINE_TCP_INVERSE, CNCROT_MACHINE_FORWARD.
