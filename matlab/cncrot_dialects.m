% CNCROT_DIALECTS  The codes of the controller dialects of cncrot_program_lines and
%   cncrot_program_write: SINUMERIK 1, HEIDENHAIN 2, FANUC 3, SYNTEC 4, TWINCAT 5, HAAS 6.
%
%   Example:
%     d = cncrot_dialects(); cncrot_program_lines(d.FANUC, 'G68.2 X10 I0 J30 K0')
function d = cncrot_dialects()
  d = struct('SINUMERIK', 1, 'HEIDENHAIN', 2, 'FANUC', 3, 'SYNTEC', 4, 'TWINCAT', 5, 'HAAS', 6);
end
