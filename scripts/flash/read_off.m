% [v, f] = read_off(path): vertices (n x 3) and triangles (m x 3, 1-based) of an OFF file
% (comment lines starting with '#' skipped; triangles only).
function [v, f] = read_off(path)
  fid = fopen(path, 'r');
  if fid < 0, error('cannot open %s', path); end
  line = next_line(fid);
  if strncmp(line, 'OFF', 3), line = strtrim(line(4:end)); end
  if isempty(line), line = next_line(fid); end
  counts = sscanf(line, '%d');
  v = fscanf(fid, '%f', [3 counts(1)])';
  f = fscanf(fid, '%d', [4 counts(2)])';
  fclose(fid);
  if any(f(:, 1) ~= 3), error('%s: only triangles are read', path); end
  f = f(:, 2:4) + 1;
end

function line = next_line(fid)
  line = '';
  while isempty(line) || line(1) == '#'
    line = strtrim(fgetl(fid));
  end
end
