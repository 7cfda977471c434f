% CNCROT_MACHINE_FORWARD  The tool frame of a machine at rotary-axis positions.
%   F = cncrot_machine_forward(MACHINE, AXES) for AXES N-by-3 (degrees, in the order the
%   axes are described; unused axes 0) gives 4-by-4-by-N frames F = W^-1 * T: the tool
%   frame relative to the workpiece; F(1:3,3) is the tool direction, F * [0;0;-L;1] the
%   tool tip of a tool of length L.
%   MACHINE is SINUMERIK swivel-data text ($TC_CARR1[1]=... lines, data set 1) or a
%   K-by-12 matrix, one row per rotary axis, outermost first:
%   [work_side vx vy vz px py pz min max offset hirth_offset hirth_step] (work_side 0: the
%   axis turns the tool, 1: the workpiece; min = max = 0: no travel limits; hirth_step 0:
%   no Hirth grid). The text may be char or a string.
%
%   Example (a fork head: C about Z carrying B about Y, pivot 150 mm above the adapter):
%     head = [0 0 0 1 0 0 0 0 0 0 0 0; 0 0 1 0 0 0 150 -100 100 0 0 0];
%     F = cncrot_machine_forward(head, [30 40 0]);   % F(1:3,3) = tool direction
%
%   See also CNCROT_MACHINE_INVERSE, CNCROT_MACHINE_CHOOSE.
