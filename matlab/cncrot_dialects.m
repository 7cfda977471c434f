% CNCROT_DIALECTS  The codes of the controller dialects.
%   d = cncrot_dialects() gives a struct of the codes the program functions
%   (cncrot_program_lines, cncrot_program_write, ...) take: SINUMERIK 1, HEIDENHAIN 2,
%   FANUC 3, SYNTEC 4, TWINCAT 5, HAAS 6.
%   Those functions take the names as well, in any case, char or string: 'sinumerik',
%   'heidenhain', 'fanuc', 'syntec', 'twincat', 'haas'.
%
%   Example:
%     d = cncrot_dialects(); cncrot_program_lines(d.FANUC, 'G68.2 X10 I0 J30 K0')
%     cncrot_program_lines('fanuc', 'G68.2 X10 I0 J30 K0')   % the same
%
%   See also CNCROT_PROGRAM_LINES, CNCROT_PROGRAM_WRITE, CNCROT_FORMS.
function d = cncrot_dialects()
  d = struct('SINUMERIK', 1, 'HEIDENHAIN', 2, 'FANUC', 3, 'SYNTEC', 4, 'TWINCAT', 5, 'HAAS', 6);
end
