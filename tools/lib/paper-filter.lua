-- paper-filter.lua -- pandoc Lua filter: fills the placeholders of paper.md from the results.
--
-- usage: pandoc paper.md --lua-filter tools/lib/paper-filter.lua ...   (tools/render-paper runs it)
-- Works with pandoc >= 2.17 (Debian 12). Placeholders (the same as the former tools/mkpaper's):
--   <!-- summary-table -->                 verdict table over all experiments      (each alone on a line)
--   <!-- results: PAPER/EXP -->            band table of one experiment
--   <!-- figure: PAPER/EXP/NAME.png -->    image (optional " | caption" after the path)
--   <!-- tsv: path/to/file.tsv -->         a TSV file (relative to DPD_ROOT) as a table
--   <!-- table: PAPER/EXP/NAME.tsv -->     results/PAPER/EXP/TIER/NAME.tsv as a table, TIER = paper if
--                                          its results exist, else reduced, else quick (marked); a column
--                                          whose header ends in "@" holds band quantity names, shown as
--                                          their verdict
--   <!-- environment -->                   tool and library versions
--   <!-- verdict: PAPER/EXP -->            the experiment's verdict in one line (the head of its card)
--   <!-- claims: PAPER/EXP -->             its claims by group (experiments/PAPER/EXP/claims.tsv): claim,
--                                          paper, ours, band, outcome; a group of several rows shows its
--                                          counts and its worst row
--   {{PAPER/EXP:QUANTITY}} (inline)        "value +- stderr" from the paper-tier summary
--                                          (else the reduced, else the quick tier, marked)
--   {{PAPER/EXP:QUANTITY:FMT}}             the value in the printf number format FMT (%.2f, %.1e ...),
--                                          "+- stderr" after it only if the stderr is positive
--   {{verdict:PAPER/EXP}}                  the experiment's verdict from its bands, with the tier
--   {{outcome:PAPER/EXP[@TIER]:QUANTITY}}  the outcome of one claim or gate row (PASS, FAIL, UNRESOLVED
--                                          and its deciding factor) at the verdict's tier, or at TIER
--   {{cpu:PAPER/EXP}}                      CPU seconds of the tier its numbers come from (provenance.tsv,
--                                          rounded; the tier is named unless it is paper); several
--                                          experiments joined by '+': their total
--   {{cpu-h:PAPER/EXP[+...]}}              the same in CPU-hours (3 significant digits)
--   {{PAPER/EXP@TIER:QUANTITY}}, {{cpu:PAPER/EXP@TIER}}
--                                          the same from that tier only, marked unless the tier is paper
--   {{tsv:PATH:ROW:COL}}                   one cell of a TSV file (PATH relative to DPD_ROOT, no ':'):
--                                          '#' lines skipped, the first other line is the header; ROW the
--                                          first column's value, or NAME=VALUE (several joined by &) for
--                                          the first row whose column NAME holds VALUE; COL a column name
--                                          (a number printed to 4 digits), or COL+-SECOL for
--                                          "value +- stderr"; a PATH under results/PAPER/EXP/TIER/ must
--                                          be a valid result and is marked unless TIER is paper
--   {{bench:FILE:ROW:COL}}                 one cell of bench/FILE (make bench) with the date and commit
--                                          of its "date, commit" row; "not measured (run `make bench`)"
--                                          if the file or the row is absent
-- Arithmetic a section needs is a quantity its experiment's analysis (run.sh) writes, not an expression here:
-- there is no expression language: {{calc:...}}, its former one, and the derived values {{pct:}}, {{ratio:}},
-- {{diff:}}, {{sigmas:}} (a percentage, ratio, difference or difference in standard errors of two
-- quantities) are errors naming the placeholder (issue 40): the analysis writes such a number as a quantity.
-- The summary table (<!-- summary-table -->) opens with one sentence per paper and every claim by group,
-- each experiment linked to its section (a heading "## PAPER/EXP: ..." gets the anchor exp-PAPER-EXP).
-- Each placeholder's expansion is markdown, read by pandoc's markdown reader in its place. An inline
-- placeholder is found in the markdown of the paragraph that holds it (the reader may have taken a
-- '*' or '^' inside it for emphasis or a superscript: written back, they are the source again).
-- Errors: a referenced result, figure or file missing, a figure older than a summary.tsv of its
-- experiment, a malformed placeholder: each is named on stderr (FILE:LINE: PLACEHOLDER: reason), and
-- pandoc exits 1 writing nothing. MKPAPER_ALLOW_MISSING=1 (drafts): warnings, the gap marked in the
-- output, exit 0. A placeholder that names the quick tier (@quick, results/P/E/quick/..., a figure
-- NAME-quick.png) while results/P/E/quick holds neither summary.tsv nor INCOMPLETE (never committed;
-- `make figures` computes it) is no error: it reads as an unobtrusive mark (an em dash, span
-- .quick-pending), its section gets one notice after its heading (div .quick-notice: "This section
-- quotes quick-tier numbers, which a fresh clone does not have: run `make figures`"), and one
-- stderr line counts them. An unpinned placeholder that finds no result stays an error.
-- In HTML every table sits in a div .table-wrap, which scrolls sideways (tools/lib/paper.css).
-- Verdicts come from tools/check --verdicts and --tsv (tools/lib/verdict.awk and bands.awk: one source
-- of truth with make check and results/verdicts.tsv);
-- the summary table's inputs column from build/freshness.tsv (tools/verify-results).
-- env: DPD_ROOT (default the repository top), MKPAPER_ALLOW_MISSING, MKPAPER_FRESHNESS
--      (default $DPD_ROOT/build/freshness.tsv)

local NAME = 'paper-filter'
local TOOLS = (PANDOC_SCRIPT_FILE or 'tools/lib/paper-filter.lua'):match('^(.*)/lib/[^/]*$') or 'tools'
local ROOT = os.getenv('DPD_ROOT') or (TOOLS .. '/..')
local ALLOW = os.getenv('MKPAPER_ALLOW_MISSING') == '1'
local FRESHNESS = os.getenv('MKPAPER_FRESHNESS') or (ROOT .. '/build/freshness.tsv')
local TIERS = { 'paper', 'reduced', 'quick' }
-- a number of a quick tier not computed here: an unobtrusive mark in the sentence (a span, so that
-- its section gets one notice, QUICK_NOTICE, after its heading: quick_notices below)
local QUICK_CLASS = 'quick-pending'
local QUICK_MARK = '[—]{.' .. QUICK_CLASS .. ' title="quick tier: run make figures"}'
local QUICK_NOTICE = 'This section quotes quick-tier numbers, which a fresh clone does not have: run `make figures`'
    .. ' (until then each shows as —).'

-- ---------------------------------------------------------------- strings and numbers

local function trim(s) return (s:gsub('^%s+', ''):gsub('%s+$', '')) end
local function split(s, sep)           -- every field, empty ones kept
    local t, i = {}, 1
    while true do
        local j = s:find(sep, i, true)
        if not j then t[#t + 1] = s:sub(i); return t end
        t[#t + 1] = s:sub(i, j - 1); i = j + #sep
    end
end
local function before(s, sep) local j = s:find(sep, 1, true); return j and s:sub(1, j - 1) or s end
local function after(s, sep) local j = s:find(sep, 1, true); return j and s:sub(j + #sep) or nil end
local function before_last(s, sep) return s:match('^(.*)' .. sep) or s end
local function after_last(s, sep) return s:match('.*' .. sep .. '(.*)$') or s end

-- a decimal number as the awk tools accept it: [+-](digits[.digits]|.digits)[e[+-]digits]
local function is_number(s)
    if type(s) ~= 'string' then return false end
    local m = s:match('^[+-]?%d+%.?%d*$') or s:match('^[+-]?%.%d+$')
        or s:match('^[+-]?%d+%.?%d*[eE][+-]?%d+$') or s:match('^[+-]?%.%d+[eE][+-]?%d+$')
    return m ~= nil
end

-- a string's numeric value as awk (mawk: strtod) takes it: nan, inf, a leading number, else 0
local NAN = math.abs(0 / 0)
local function awk_number(s)
    s = trim(s or '')
    local n = tonumber(s)
    if n and not s:match('^[+-]?0[xX]') then return n end
    local sign, word = s:lower():match('^([+-]?)(%a+)')
    if word == 'nan' then return sign == '-' and -NAN or NAN end
    if word == 'inf' or word == 'infinity' then return sign == '-' and -math.huge or math.huge end
    local lead = s:match('^[+-]?%d*%.?%d+[eE][+-]?%d+') or s:match('^[+-]?%d+%.?%d*') or s:match('^[+-]?%.%d+')
    return tonumber(lead or '') or 0
end
local function fmt(p, s) return string.format(p, awk_number(s)) end
local function fmt_if_number(p, s) return is_number(s) and fmt(p, s) or s end
local function md_escape(s) return (s:gsub('[|*_<>`\\]', '\\%0')) end
local function pipe_escape(s) return (s:gsub('|', '\\|')) end

-- ---------------------------------------------------------------- files and commands

local function exists(path) local f = io.open(path, 'r'); if f then f:close(); return true end; return false end
local function is_nonempty(path)
    local f = io.open(path, 'r'); if not f then return false end
    local size = f:seek('end'); f:close(); return size ~= nil and size > 0
end
local function read_lines(path)         -- nil if unreadable; '\r' of CRLF files dropped
    local f = io.open(path, 'r'); if not f then return nil end
    local t = {}
    for l in f:lines() do t[#t + 1] = l:gsub('\r$', '') end
    f:close(); return t
end
-- the lines of a TSV file that are data ('#' and blank lines skipped), split: the header's fields
-- (nil for no data), its columns by name, the other rows
local function tsv_rows(lines)
    local header, columns, rows = nil, {}, {}
    for _, l in ipairs(lines) do
        if not (l:match('^#') or l:match('^[ \t]*$')) then
            if header then rows[#rows + 1] = split(l, '\t')
            else header = split(l, '\t'); for i, c in ipairs(header) do columns[c] = i end end
        end
    end
    return header, columns, rows
end

local function shell_quote(s) return "'" .. s:gsub("'", "'\\''") .. "'" end
-- the lines a shell command prints, and whether it exited 0
local function command_lines(cmd)
    local p = io.popen(cmd); local t = {}
    for l in p:lines() do t[#t + 1] = l end
    return t, p:close() == true
end
local function first_line(cmd) return command_lines('{ ' .. cmd .. '; } 2>/dev/null')[1] or '' end

-- ---------------------------------------------------------------- reporting

local nerr, npend, pending_ids = 0, 0, {}
local source_lines = nil

-- the line of the input that holds TEXT (for messages; 0 if not found)
local function line_of(text)
    if source_lines == nil then
        local input = PANDOC_STATE and PANDOC_STATE.input_files and PANDOC_STATE.input_files[1]
        source_lines = (input and input ~= '-' and read_lines(input)) or {}
    end
    for i, l in ipairs(source_lines) do if l:find(text, 1, true) then return i end end
    return 0
end
local function input_name()
    local input = PANDOC_STATE and PANDOC_STATE.input_files and PANDOC_STATE.input_files[1]
    return input and input:match('[^/]*$') or 'stdin'
end

-- report a problem with placeholder PH; returns the draft note (markdown) or ''
local function problem(ph, msg)
    io.stderr:write(string.format('%s: %s:%d: %s: %s\n', NAME, input_name(), line_of(ph), ph, msg))
    if ALLOW then return string.format('\n**[missing: %s -- %s]**\n\n', md_escape(ph), md_escape(msg)) end
    nerr = nerr + 1
    return ''
end
-- an inline placeholder that could not be filled: reported, replaced by a bold "missing"
local function missing(ph, msg, shown) problem(ph, msg); return '**' .. shown .. '**' end
-- a placeholder that awaits experiment ID's quick tier (counted once per placeholder)
local function pending(id) npend = npend + 1; pending_ids[id] = true; return QUICK_MARK end

-- ---------------------------------------------------------------- results

local function valid_result(id, tier)
    local r = ROOT .. '/results/' .. id .. '/' .. tier
    return exists(r .. '/summary.tsv') and not exists(r .. '/INCOMPLETE')
end
-- the experiment exists and its quick tier (never committed) has not been computed here
local function awaits_quick(id)
    local r = ROOT .. '/results/' .. id .. '/quick'
    return exists(ROOT .. '/experiments/' .. id) and not exists(r .. '/summary.tsv') and not exists(r .. '/INCOMPLETE')
end
-- the fields of the first line of FILE whose first field is KEY
local function row_with_key(file, key)
    for _, l in ipairs(read_lines(file) or {}) do
        local f = split(l, '\t')
        if f[1] == key then return f end
    end
end
local function provenance(id, tier, key)
    local f = row_with_key(ROOT .. '/results/' .. id .. '/' .. tier .. '/provenance.tsv', key)
    return f and f[2] or ''
end
-- value and stderr (strings) of quantity Q in results/ID/TIER/summary.tsv, or nil
local function summary_value(id, tier, q)
    local f = row_with_key(ROOT .. '/results/' .. id .. '/' .. tier .. '/summary.tsv', q)
    if f then return f[2] or '', f[3] or '' end
end

-- the band rows of every experiment at TIER, from tools/check --tsv (lib/bands.awk), by experiment:
-- eid quantity value stderr lo hi k paper verdict dist source note
local band_cache = {}
local function band_rows(id, tier)
    if not band_cache[tier] then
        local by = {}
        local cmd = 'DPD_ROOT=' .. shell_quote(ROOT) .. ' ' .. shell_quote(TOOLS .. '/check') .. ' --tsv --tier ' .. shell_quote(tier)
        local lines, ok = command_lines(cmd)
        if not ok then problem('tools/check --tsv --tier ' .. tier, 'failed (its rows give every verdict)') end
        for _, l in ipairs(lines) do
            local f = split(l, '\t')
            by[f[1]] = by[f[1]] or {}
            table.insert(by[f[1]], f)
        end
        band_cache[tier] = by
    end
    return band_cache[tier][id] or {}
end

-- the experiment ids of the summary table (EXPERIMENTS.md, then experiments/*/*/; lib/common.sh)
local function experiment_ids()
    local cmd = 'DPD_ROOT=' .. shell_quote(ROOT) .. ' bash -c ' .. shell_quote('. "$0"; list_md_ids; list_exp_dirs')
        .. ' ' .. shell_quote(TOOLS .. '/lib/common.sh')
    local ids, seen = {}, {}
    for _, id in ipairs(command_lines(cmd)) do
        if not seen[id] then seen[id] = true; ids[#ids + 1] = id end
    end
    return ids
end

-- the verdicts of every experiment (tools/check --verdicts --tier auto, lib/verdict.awk: one source
-- with make check and results/verdicts.tsv), by experiment: tier ('-' if none), verdict, counts of
-- claims passed / failed / unresolved / missing, gates passed / total, regression references,
-- decide (the run-length factor that would decide the unresolved claims), worst, cpu
local verdict_cache
local function verdict_of(id)
    if not verdict_cache then
        verdict_cache = {}
        local cmd = 'DPD_ROOT=' .. shell_quote(ROOT) .. ' ' .. shell_quote(TOOLS .. '/check') .. ' --verdicts --tier auto'
        local lines, ok = command_lines(cmd)
        if not ok then problem('tools/check --verdicts', 'failed (it gives every verdict)') end
        for i, l in ipairs(lines) do
            local f = split(l, '\t')
            if i > 1 and #f >= 14 then
                verdict_cache[f[1]] = { tier = f[2], verdict = f[3], cp = tonumber(f[4]), cf = tonumber(f[5]),
                    cu = tonumber(f[6]), cm = tonumber(f[7]), gp = tonumber(f[8]), gt = tonumber(f[9]),
                    rp = tonumber(f[10]), rt = tonumber(f[11]), decide = f[12], worst = f[13], cpu = f[14] }
            end
        end
    end
    local v = verdict_cache[id]
    if v then return v end
    if not exists(ROOT .. '/experiments/' .. id) then
        return { tier = '-', verdict = 'not yet built', cp = 0, cf = 0, cu = 0, cm = 0, gp = 0, gt = 0, rp = 0, rt = 0, decide = '-', worst = '-', cpu = '-' }
    end
    -- a method study without bands.tsv (tools/check lists only experiments with one): run, but no
    -- claims to decide; its tier is the highest committed (before, the table said "not run")
    if not exists(ROOT .. '/experiments/' .. id .. '/bands.tsv') then
        for _, t in ipairs({ 'paper', 'reduced', 'quick' }) do
            if valid_result(id, t) then
                local cpu = provenance(id, t, 'cpu_seconds')
                return { tier = t, verdict = 'no claims', cp = 0, cf = 0, cu = 0, cm = 0, gp = 0, gt = 0, rp = 0, rt = 0,
                         decide = '-', worst = '-', cpu = cpu ~= '' and cpu or '-' }
            end
        end
    end
    return { tier = '-', verdict = 'not run', cp = 0, cf = 0, cu = 0, cm = 0, gp = 0, gt = 0, rp = 0, rt = 0, decide = '-', worst = '-', cpu = '-' }
end

-- the claims of ID at TIER by outcome: PASS, FAIL (with XFAIL), UNRESOLVED; each a list of names
local function claims_by_outcome(id, tier)
    local by = { PASS = {}, FAIL = {}, UNRESOLVED = {} }
    for _, r in ipairs(band_rows(id, tier)) do
        if r[13] == 'claim' then
            local o = r[9] == 'XFAIL' and 'FAIL' or r[9]
            if by[o] then table.insert(by[o], r[2]) end
        end
    end
    return by
end

-- "name, name, ... and N more" (at most SHOWN names, in code font)
local function name_list(names, shown)
    local t = {}
    for i = 1, math.min(#names, shown) do t[i] = '`' .. names[i] .. '`' end
    local s = table.concat(t, ', ')
    if #names > shown then s = s .. string.format(' and %d more', #names - shown) end
    return s
end

-- the inputs column of the summary table (build/freshness.tsv from tools/verify-results)
local function freshness_of(id, tier)
    if tier == '-' then return '-' end
    for _, l in ipairs(read_lines(FRESHNESS) or {}) do
        local f = split(l, '\t')
        if f[1] == id and f[2] == tier then
            return f[3] == 'fresh' and 'reanalysed' or f[3] == 'unverifiable' and 'scenes checked' or '**STALE**'
        end
    end
    return '-'
end

-- ---------------------------------------------------------------- block placeholders (markdown out)

-- ---------------------------------------------------------------- claim groups and the summary a reviewer reads first

-- the claim groups (experiments/P/E/claims.tsv; tools/check --groups --tsv, lib/groups.awk: every claim
-- row in exactly one group, else an error): by experiment, the groups in their file's order
-- ({name, statement, paper}) and each claim quantity's group number
local groups_cache
local function claim_groups(id)
    if not groups_cache then
        groups_cache = {}
        local cmd = 'DPD_ROOT=' .. shell_quote(ROOT) .. ' ' .. shell_quote(TOOLS .. '/check') .. ' --groups --tsv'
        local lines, ok = command_lines(cmd)
        if not ok then
            problem('claims.tsv', 'tools/check --groups: a claim row in no group or in two, or a malformed claims.tsv (named above)')
        end
        for _, l in ipairs(lines) do
            local f = split(l, '\t')
            groups_cache[f[1]] = groups_cache[f[1]] or { of = {} }
            groups_cache[f[1]].of[f[2]] = tonumber(f[3])
        end
    end
    local g = groups_cache[id] or { of = {} }
    if not g.list then
        g.list = {}
        local _, _, rows = tsv_rows(read_lines(ROOT .. '/experiments/' .. id .. '/claims.tsv') or {})
        for i, f in ipairs(rows) do g.list[i] = { name = trim(f[1] or ''), statement = trim(f[3] or ''), paper = trim(f[4] or '') } end
        groups_cache[id] = g
    end
    return g
end

-- text read by pandoc's markdown reader as it is (no emphasis, superscript, math, link or raw HTML)
local function md_text(s) return (s:gsub('[|*_<>`\\%^~%[%]%$@#]', '\\%0')) end

-- the section of experiment ID (its heading "## ID: ..."): its anchor, and whether paper.md has it
local function anchor_of(id) return 'exp-' .. id:gsub('[^%w%-%.]', '-') end
local sections = {}

-- an outcome as a coloured word (paper.css .outcome), with a count before it if N
local OUTCOME_CLASS = { PASS = 'pass', FAIL = 'fail', UNRESOLVED = 'unresolved' }
local function outcome_span(word, n, title)
    return string.format('[%s%s]{.outcome .%s%s}', n and (n .. ' ') or '', word, OUTCOME_CLASS[word] or 'other',
                         title and (' title="' .. title .. '"') or '')
end

-- band row R's outcome as a coloured word (XFAIL as FAIL, titled; UNRESOLVED with the factor of
-- the run length that decides it): the claims tables and {{outcome:}}
local function row_outcome(r)
    local o = r[9] == 'XFAIL' and 'FAIL' or r[9]
    local text = OUTCOME_CLASS[o] and outcome_span(o, nil, r[9] == 'XFAIL' and 'a known non-reproduction (expect = fail)' or nil)
        or '**' .. r[9] .. '**'
    if r[9] == 'UNRESOLVED' and (r[15] or '-') ~= '-' then text = text .. ' (×' .. r[15] .. ' run)' end
    return text
end

-- band row R (tools/check --tsv) as "value ± se", "[lo, hi]"
local function row_ours(r)
    if r[3] == '-' then return 'missing' end
    return fmt_if_number('%.4g', r[3]) .. ' ± ' .. fmt_if_number('%.2g', r[4])
end
local function row_band(r) return '[' .. r[5] .. ', ' .. r[6] .. ']' end
local function row_distance(r)
    if r[3] ~= '-' and not is_number(r[3]) then return -2 end   -- no finite value: worst only if none has one
    if r[10] == 'inf' then return math.huge end
    return is_number(r[10]) and awk_number(r[10]) or -1
end

-- the outcome's rank for a group's worst row: a failing row before an unresolved one before a pass
-- (so the row shown is one that sets the group's outcome), anything else (missing, malformed) first
local OUTCOME_RANK = { PASS = 1, UNRESOLVED = 2, FAIL = 3, XFAIL = 3 }
local function worse_than(r, w)
    local a, b = OUTCOME_RANK[r[9]] or 4, OUTCOME_RANK[w[9]] or 4
    if a ~= b then return a > b end
    return row_distance(r) > row_distance(w)
end

-- one row per claim group of ID at TIER, in the order of its claims.tsv: the group's name,
-- statement and paper number; its rows' outcomes counted (XFAIL is a FAIL, one already known);
-- one row: our value, the band and the outcome; several: the counts, and the worst row: of the
-- worst outcome (worse_than), the one farthest from its band's centre (for a group that passes, the
-- closest to an edge), among the rows with a finite value if any has one (the count of those
-- without, nan or inf, said beside it). Claims of no group
-- (claims.tsv broken: an error, reported) come last, one group each.
local function group_rows(id, tier)
    local g = claim_groups(id)
    local groups, extra = {}, {}
    for i, d in ipairs(g.list) do groups[i] = { name = d.name, statement = d.statement, paper = d.paper, rows = {} } end
    for _, r in ipairs(band_rows(id, tier)) do
        if r[13] == 'claim' then
            local k = g.of[r[2]]
            if k and groups[k] then table.insert(groups[k].rows, r)
            else extra[#extra + 1] = { name = r[2], statement = '(in no group of claims.tsv)', paper = r[8], rows = { r } } end
        end
    end
    for _, e in ipairs(extra) do groups[#groups + 1] = e end
    local out = {}
    for _, grp in ipairs(groups) do
        if #grp.rows > 0 then
            local c, worst, others = { PASS = 0, FAIL = 0, UNRESOLVED = 0 }, nil, {}
            for _, r in ipairs(grp.rows) do
                local o = (r[9] == 'XFAIL') and 'FAIL' or r[9]
                if c[o] then c[o] = c[o] + 1
                else
                    if not c[o .. '?'] then others[#others + 1] = o end
                    c[o .. '?'] = (c[o .. '?'] or 0) + 1
                end
                if not worst or worse_than(r, worst) then worst = r end
            end
            local row = { name = grp.name, statement = grp.statement, paper = grp.paper, n = #grp.rows, counts = c }
            if #grp.rows == 1 then
                local r = grp.rows[1]
                row.ours = row_ours(r); row.band = row_band(r)
                row.outcome = row_outcome(r)
            else
                row.ours = 'worst of ' .. #grp.rows .. ': `' .. worst[2] .. '` ' .. row_ours(worst)
                local novalue = 0
                for _, r in ipairs(grp.rows) do if r[3] ~= '-' and not is_number(r[3]) then novalue = novalue + 1 end end
                if novalue > 0 and novalue < #grp.rows then row.ours = row.ours .. string.format(' (%d without a finite value)', novalue) end
                row.band = row_band(worst)
                local parts = {}
                for _, o in ipairs({ 'PASS', 'FAIL', 'UNRESOLVED' }) do
                    if c[o] > 0 then parts[#parts + 1] = outcome_span(o, c[o]) end
                end
                for _, o in ipairs(others) do parts[#parts + 1] = string.format('**%d %s**', c[o .. '?'], o) end
                row.outcome = table.concat(parts, ' ')
            end
            out[#out + 1] = row
        end
    end
    return out
end

local function cpu_hours(v)
    if not is_number(v.cpu) then return '-' end
    return string.format('%.2g', awk_number(v.cpu) / 3600)
end
local function gates_cell(v)
    if v.tier == '-' then return '-' end
    if v.gt == 0 then return 'none' end
    local s = string.format('%d / %d', v.gp, v.gt)
    if v.verdict == 'invalid' then s = '**invalid** (' .. s .. ')' end
    return s
end
local VERDICT_CLASS = { ['[Re]'] = 'pass', ['[¬Re]'] = 'fail', ['[~Re]'] = 'partial', unresolved = 'unresolved', invalid = 'fail' }
local function verdict_span(v) return '[' .. md_text(v) .. ']{.verdict .' .. (VERDICT_CLASS[v] or 'other') .. '}' end

-- per paper (the first part of the ids), one sentence: how many of its experiments reproduce, in
-- part, not, undecided, invalid, not run; its claims by outcome; the CPU-hours of the tiers shown
local function paper_sentences(ids)
    local order, by = {}, {}
    for _, id in ipairs(ids) do
        local p = before(id, '/')
        if not by[p] then by[p] = { n = 0, v = {}, cp = 0, cf = 0, cu = 0, cpu = 0 }; order[#order + 1] = p end
        local b, v = by[p], verdict_of(id)
        b.n = b.n + 1; b.v[v.verdict] = (b.v[v.verdict] or 0) + 1
        b.cp = b.cp + v.cp; b.cf = b.cf + v.cf; b.cu = b.cu + v.cu
        if is_number(v.cpu) then b.cpu = b.cpu + awk_number(v.cpu) end
    end
    local out = {}
    for _, p in ipairs(order) do
        local b = by[p]
        local parts = { string.format('%d of %d experiments reproduce ([Re])', b.v['[Re]'] or 0, b.n) }
        local function add(key, what) if (b.v[key] or 0) > 0 then parts[#parts + 1] = string.format('%d %s', b.v[key], what) end end
        add('[~Re]', 'in part ([~Re])'); add('[¬Re]', 'not ([¬Re])'); add('unresolved', 'undecided (unresolved)')
        add('invalid', 'invalid (a gate does not pass)'); add('not run', 'not run'); add('no claims', 'run without claims (a method study)'); add('not yet built', 'not yet built')
        add('missing', 'with a value missing'); add('bad bands', 'with malformed bands')
        out[#out + 1] = string.format('- **%s**: %s; of their %d claims %d pass, %d fail and %d are unresolved; %.3g CPU-hours.',
            p, table.concat(parts, ', '), b.cp + b.cf + b.cu, b.cp, b.cf, b.cu, b.cpu / 3600)
    end
    return table.concat(out, '\n') .. '\n\n'
end

local CLAIMS_CAPTION = 'The paper\'s number as the paper prints it; ours ± its standard error; the band (the paper\'s'
    .. ' number with its tolerance); the outcome under the decision rule (pass: value ± 2 stderr inside the band; fail:'
    .. ' wholly outside; unresolved: neither). A group of several rows shows its counts and its worst row (the farthest'
    .. ' from its band\'s centre among those of the worst outcome with a finite value).'

-- the claims table of the summary: per experiment one row per claim group, with its verdict, gates,
-- tier and CPU-hours on its first row, and a link to its section
local function claims_summary(ids)
    claim_groups('')    -- the groups of every experiment checked, whether it has results or not
    -- the separator's dashes set the columns' relative widths (pandoc: a pipe table wider than a line)
    local out = { '', '::: {.claims-table}', '', '| experiment | claim | paper | ours | band | outcome | gates | tier | CPU-h |',
                  '|:' .. ('-'):rep(12) .. '|:' .. ('-'):rep(27) .. '|:' .. ('-'):rep(8) .. '|:' .. ('-'):rep(15)
                  .. '|:' .. ('-'):rep(8) .. '|:' .. ('-'):rep(10) .. '|:' .. ('-'):rep(6) .. '|:' .. ('-'):rep(7) .. '|' .. ('-'):rep(7) .. ':|' }
    for _, id in ipairs(ids) do
        local v = verdict_of(id)
        local name = sections[id] and string.format('[`%s`](#%s)', id, anchor_of(id)) or '`' .. id .. '`'
        local head = name .. ' ' .. verdict_span(v.verdict)
        local rows = v.tier ~= '-' and group_rows(id, v.tier) or {}
        local tier = v.tier ~= '-' and v.tier or '-'
        if #rows == 0 then
            out[#out + 1] = string.format('| %s | - | - | - | - | - | %s | %s | %s |', head, gates_cell(v), tier, cpu_hours(v))
        end
        for i, r in ipairs(rows) do
            out[#out + 1] = string.format('| %s | **%s**: %s | %s | %s | %s | %s | %s | %s | %s |', i == 1 and head or '',
                md_text(r.name), md_text(r.statement), md_text(r.paper), r.ours, r.band, r.outcome,
                i == 1 and gates_cell(v) or '', i == 1 and tier or '', i == 1 and cpu_hours(v) or '')
        end
    end
    out[#out + 1] = ''
    out[#out + 1] = ': Every claim of every experiment, by claim group (experiments/P/E/claims.tsv), from the tier shown. '
        .. CLAIMS_CAPTION .. ' Gates: the set-up checks passed of all (a gate that does not pass makes the result invalid).'
    out[#out + 1] = ''
    out[#out + 1] = ':::'
    out[#out + 1] = ''
    return table.concat(out, '\n') .. '\n'
end

-- <!-- verdict: P/E -->: the experiment's verdict in one line, first in its card
local function verdict_block(ph, arg)
    local id = trim(arg)
    local v = verdict_of(id)
    if v.tier == '-' then return problem(ph, 'no results for ' .. id) end
    local claims = string.format('claims %d pass, %d fail, %d unresolved', v.cp, v.cf, v.cu) .. (v.cm > 0 and string.format(', %d missing', v.cm) or '')
    return string.format('\n**Verdict:** %s (%s tier; %s; gates %s; %s CPU-hours)\n\n', verdict_span(v.verdict), v.tier, claims,
        v.gt == 0 and 'none' or string.format('%d of %d', v.gp, v.gt), cpu_hours(v))
end

-- <!-- claims: P/E -->: the experiment's claim groups as a short table (its card)
local function claims_block(ph, arg)
    local id = trim(arg)
    if not exists(ROOT .. '/experiments/' .. id .. '/bands.tsv') then return problem(ph, 'no experiments/' .. id .. '/bands.tsv') end
    local v = verdict_of(id)
    if v.tier == '-' then return problem(ph, 'no results for ' .. id) end
    local rows = group_rows(id, v.tier)
    if #rows == 0 then return '\n*No claims at the ' .. v.tier .. ' tier.*\n\n' end
    local out = { '', '::: {.claims-table}', '', '| claim | paper | ours | band | outcome |',
                  '|:' .. ('-'):rep(40) .. '|:' .. ('-'):rep(12) .. '|:' .. ('-'):rep(22) .. '|:' .. ('-'):rep(12) .. '|:' .. ('-'):rep(14) .. '|' }
    for _, r in ipairs(rows) do
        out[#out + 1] = string.format('| **%s**: %s | %s | %s | %s | %s |', md_text(r.name), md_text(r.statement), md_text(r.paper),
            r.ours, r.band, r.outcome)
    end
    out[#out + 1] = ''
    out[#out + 1] = ': `' .. id .. '`: its claims by group, ' .. v.tier .. ' tier. ' .. CLAIMS_CAPTION
    out[#out + 1] = ''
    out[#out + 1] = ':::'
    out[#out + 1] = ''
    return table.concat(out, '\n') .. '\n'
end

local SUMMARY_CAPTION = table.concat({
    ': Reproduction status, from the bands of the tier shown (paper if its results exist, else reduced, else quick).',
    'Each row of a bands.tsv is a *claim* (a number or shape the paper states, or theory with a stated tolerance)',
    'or a *gate* (a check that the set-up is right). A claim passes when value ± 2 stderr lies inside its band',
    '(the paper\'s number with its tolerance, never widened by the run\'s error), fails when it lies wholly outside,',
    'and is unresolved otherwise. Verdict, from the claims only: [Re] every claim passes, [¬Re] every claim fails,',
    '[~Re] some pass and some fail, *unresolved* when the run cannot decide; *invalid* when a gate does not pass',
    '(the result is then no evidence either way). Decide: how many times longer the runs must be to decide its',
    'unresolved claims (the largest over them, if the value stays where it is and the error falls as 1/√length),',
    'and the CPU-hours the experiment would then take (its runs scaled alike).',
    'CPU s: cpu_seconds from provenance.tsv.',
    'Inputs (tools/verify-results, run by make paper): *reanalysed* -- the analysis, redone by the current run.sh',
    'from the kept simulation outputs, reproduces every table, and every simulation it asks for was made with',
    'the same arguments and scene; *scenes checked* -- the analysis cannot be redone from the kept files (reason',
    'in build/freshness.tsv), its scene files are unchanged since the result was committed; *STALE* -- cited anyway (draft).',
    'The simulator binary is not checked: each result records the commit it was built from.' }, ' ')

-- the paper tier's CPU hours per paper, from the provenance files
local function paper_cpu_line(ids)
    local hours, count, papers = {}, {}, {}
    for _, id in ipairs(ids) do
        if valid_result(id, 'paper') then
            local p = before(id, '/')
            if not hours[p] then hours[p] = 0; count[p] = 0; papers[#papers + 1] = p end
            hours[p] = hours[p] + awk_number(provenance(id, 'paper', 'cpu_seconds')); count[p] = count[p] + 1
        end
    end
    table.sort(papers)
    local parts = {}
    for i, p in ipairs(papers) do
        parts[i] = string.format('%s `%s` %.2f h (%d experiments)', i > 1 and ';' or '', p, hours[p] / 3600, count[p])
    end
    return 'Paper tier, CPU time of the experiments that have paper-tier results (one core):' .. table.concat(parts) .. '.\n\n'
end

local function summary_table()
    local ids = experiment_ids()
    local first = paper_sentences(ids) .. claims_summary(ids)
    local out = { '', '| experiment | verdict | claims pass / fail / unresolved | gates | tier | decide | CPU s | inputs |',
                  '|:---|:---|:---|:---|:---|---:|---:|:---|' }
    for _, id in ipairs(ids) do
        local v = verdict_of(id)
        local tier = v.tier ~= '-' and '**' .. v.tier .. '**' or '-'
        local claims = v.tier == '-' and '-' or string.format('%d / %d / %d', v.cp, v.cf, v.cu) .. (v.cm > 0 and string.format(' (%d missing)', v.cm) or '')
        local gates = v.tier == '-' and '-' or (v.gt == 0 and 'none' or string.format('%d of %d', v.gp, v.gt))
        -- the run-length factor that decides the unresolved claims, and what the experiment's runs would
        -- cost at that length (its CPU time so far times the factor: the runs scaled alike)
        local decide = v.decide
        if v.decide ~= '-' and v.decide ~= 'inf' then
            decide = string.format('×%s', v.decide)
            if is_number(v.cpu) and awk_number(v.cpu) > 0 then
                decide = decide .. string.format(' (%.2g CPU-h)', awk_number(v.decide) * awk_number(v.cpu) / 3600)
            end
        end
        out[#out + 1] = string.format('| `%s` | %s | %s | %s | %s | %s | %s | %s |', id, v.verdict, claims, gates, tier,
                                      decide, v.cpu, freshness_of(id, v.tier))
    end
    out[#out + 1] = ''; out[#out + 1] = SUMMARY_CAPTION; out[#out + 1] = ''
    return first .. table.concat(out, '\n') .. '\n' .. paper_cpu_line(ids)
end

local function verdict_cell(v)
    if v == 'PASS' then return 'pass' elseif v == 'FAIL' then return '**FAIL**' else return '**' .. v .. '**' end
end

local function results_table(ph, arg)
    local id = arg:gsub('^%./', ''):gsub('^experiments/', ''):gsub('^results/', ''):gsub('/$', '')
    if not exists(ROOT .. '/experiments/' .. id) then return problem(ph, 'no experiment directory experiments/' .. id) end
    if not exists(ROOT .. '/experiments/' .. id .. '/bands.tsv') then return problem(ph, 'no experiments/' .. id .. '/bands.tsv') end
    local rows, cpus, any = {}, {}, false
    for _, t in ipairs(TIERS) do
        if valid_result(id, t) then
            any = true
            for _, r in ipairs(band_rows(id, t)) do
                local ours = r[3] == '-' and 'missing' or fmt_if_number('%.6g', r[3]) .. ' ± ' .. fmt_if_number('%.2g', r[4])
                local band = '[' .. r[5] .. ', ' .. r[6] .. ']'
                if r[5] == r[6] then band = band .. ' ± ' .. r[7] .. ' σ' .. ((r[14] or '-') ~= '-' and ', σ ≤ ' .. r[14] or '') end
                local outcome = verdict_cell(r[9])
                if r[9] == 'UNRESOLVED' and r[13] == 'claim' and (r[15] or '-') ~= '-' then outcome = outcome .. ' (×' .. r[15] .. ' run)' end
                rows[#rows + 1] = string.format('| `%s` | %s | %s | %s | %s | %s | %s |', r[2], r[13] or '-', pipe_escape(r[8]),
                                                pipe_escape(ours), pipe_escape(band), t, outcome)
            end
            local c = provenance(id, t, 'cpu_seconds')
            cpus[#cpus + 1] = t .. ' ' .. (c ~= '' and c or '?') .. ' s'
        end
    end
    if not any then return problem(ph, 'no results/' .. id .. '/{paper,quick}/summary.tsv') end
    local out = { '' }
    if #rows == 0 then out[#out + 1] = '*No bands for the tiers that have results.*'
    else
        out[#out + 1] = '| quantity | kind | paper | ours ± stderr | band | tier | outcome |'
        out[#out + 1] = '|:---|:---|---:|---:|:---|:---|:---|'
        for _, r in ipairs(rows) do out[#out + 1] = r end
    end
    out[#out + 1] = ''
    out[#out + 1] = ': `' .. id .. '`: our values against the bands. A claim passes when value ± 2 stderr lies inside its band'
        .. ' and fails when it lies wholly outside (×N: a run N times as long would decide an unresolved one); a gate'
        .. ' of one value passes when it lies within the σ shown and its stderr is at most the resolution shown. CPU time: '
        .. table.concat(cpus, ', ') .. '.'
    return table.concat(out, '\n') .. '\n\n'
end

-- the summary.tsv files of ID's complete results, each with whether it is newer than FIG
local function results_newer_than(id, fig)
    local script = 'cd "$0" || exit; for s in results/"$1"/*/summary.tsv; do [ -f "$s" ] || continue; '
        .. '[ -e "${s%/*}/INCOMPLETE" ] && continue; if [ "$s" -nt "$2" ]; then echo "newer $s"; else echo "older $s"; fi; done'
    return command_lines('bash -c ' .. shell_quote(script) .. ' ' .. shell_quote(ROOT) .. ' ' .. shell_quote(id) .. ' ' .. shell_quote(fig))
end

local function figure_line(ph, arg)
    local spec, cap = arg, ''
    if arg:find('|', 1, true) then spec, cap = before(arg, '|'), after(arg, '|') end
    spec = trim(spec):gsub('^figures/', ''); cap = trim(cap)
    if not (spec:match('^.*/.*/.*%.png$') or spec:match('^.*/.*/.*%.svg$')) then
        return problem(ph, 'expected PAPER/EXP/NAME.png or .svg')
    end
    local rel, id, name = 'figures/' .. spec, before_last(spec, '/'), after_last(spec, '/')
    if not exists(ROOT .. '/' .. rel) then
        -- a figure of the quick tier (NAME-quick.png, plot.gp's naming) before that tier is computed
        if (name:match('%-quick%.png$') or name:match('%-quick%.svg$')) and awaits_quick(id) then
            pending(id)
            return string.format('\n*Figure* `%s`%s %s\n\n', rel, cap ~= '' and ' (' .. md_escape(cap) .. ')' or '', QUICK_MARK)
        end
        return problem(ph, 'figure ' .. rel .. ' does not exist (make figures)')
    end
    local nres, newer = 0, ''
    for _, l in ipairs(results_newer_than(id, rel)) do
        nres = nres + 1
        if l:match('^newer ') then newer = newer .. ' ' .. l:sub(7) end
    end
    if nres == 0 then return problem(ph, 'figure ' .. rel .. ': no results/' .. id .. '/*/summary.tsv it could derive from') end
    if newer ~= '' then return problem(ph, 'figure ' .. rel .. ' is older than' .. newer .. ' (re-run make figures)') end
    if cap == '' then cap = id .. ': ' .. name end
    return string.format('![%s](%s)\n', cap, rel)
end

-- the non-blank lines of a TSV file as a pipe table; VERDICT_COLUMNS: header cells ending in '@'
-- hold band quantity names, shown as their verdicts from VERDICTS (quantity -> verdict)
local function pipe_table(lines, verdicts)
    local out, ncol, is_verdict = { '' }, nil, {}
    for _, l in ipairs(lines) do
        if not l:match('^[ \t]*$') then
            local f = split(l, '\t')
            if not ncol then
                ncol = #f
                local head, sep = '|', '|'
                for i = 1, ncol do
                    local c = f[i]
                    if verdicts and c:match('@$') then is_verdict[i] = true; c = c:sub(1, -2) end
                    head = head .. ' ' .. pipe_escape(c) .. ' |'; sep = sep .. '---|'
                end
                out[#out + 1] = head; out[#out + 1] = sep
            else
                local row = '|'
                for i = 1, ncol do
                    local c = f[i] or ''
                    if is_verdict[i] then
                        local v = verdicts[c] or 'no band'
                        c = v == 'PASS' and 'pass' or v == 'no band' and 'no band' or '**' .. v .. '**'
                    end
                    row = row .. ' ' .. pipe_escape(c) .. ' |'
                end
                out[#out + 1] = row
            end
        end
    end
    return table.concat(out, '\n') .. '\n\n'
end

-- results/P/E/quick/... of an experiment whose quick tier awaits `make figures`: that experiment
local function quick_path_awaiting(p)
    local id = p:match('^results/([^/]*/[^/]*)/quick/')
    if id and awaits_quick(id) then return id end
end

local function tsv_table(ph, arg)
    local p = trim(arg)
    local f = p:sub(1, 1) == '/' and p or ROOT .. '/' .. p
    if not exists(f) then
        local id = quick_path_awaiting(p)
        if id then pending(id); return string.format('\n*Table* `%s` %s\n\n', p, QUICK_MARK) end
        return problem(ph, 'no file ' .. p)
    end
    if not is_nonempty(f) then return problem(ph, 'file ' .. p .. ' is empty') end
    return pipe_table(read_lines(f))
end

local function result_table(ph, arg)
    local spec = trim(arg)
    if not spec:match('^.*/.*/.*%.tsv$') then return problem(ph, 'expected PAPER/EXP/NAME.tsv') end
    local id, name = before_last(spec, '/'), after_last(spec, '/')
    local tier
    for _, t in ipairs(TIERS) do
        if valid_result(id, t) and is_nonempty(ROOT .. '/results/' .. id .. '/' .. t .. '/' .. name) then tier = t; break end
    end
    if not tier then return problem(ph, 'no results/' .. id .. '/{paper,quick}/' .. name) end
    local verdicts = {}
    for _, r in ipairs(band_rows(id, tier)) do verdicts[r[2]] = r[9] end
    local md = pipe_table(read_lines(ROOT .. '/results/' .. id .. '/' .. tier .. '/' .. name), verdicts)
    if tier == 'quick' then md = md .. ': `' .. id .. '`: quick tier (no paper-tier result).\n\n' end
    return md
end

local function environment_table()
    local function row(name, value) return string.format('| %s | %s |', name, md_escape(value ~= '' and value or 'not found')) end
    local function dpkg_version(pkg) return first_line("dpkg-query -W -f='${Version}' " .. pkg) end
    local h5 = first_line("h5cc -showconfig | awk -F: '/HDF5 Version/ { gsub(/^[ \\t]+|[ \\t]+$/, \"\", $2); print $2; exit }'")
    if h5 == '' then h5 = dpkg_version('libhdf5-dev') end
    local cmocka = first_line('pkg-config --modversion cmocka')
    if dpkg_version('libcmocka-dev') ~= '' then cmocka = cmocka .. ' (libcmocka-dev ' .. dpkg_version('libcmocka-dev') .. ')' end
    local out = { '', '| component | version |', '|:---|:---|',
        row('gcc', first_line('gcc --version')), row('GSL', first_line('gsl-config --version')), row('HDF5', h5),
        row('libconfig', first_line('pkg-config --modversion libconfig')), row('Random123', dpkg_version('librandom123-dev')),
        row('cmocka', cmocka), row('gnuplot', first_line('gnuplot --version')), row('pandoc', first_line('pandoc --version')),
        row('source (git describe)', first_line('git -C ' .. shell_quote(ROOT) .. ' describe --always --dirty')),
        row('kernel (uname -srm)', first_line('uname -srm')),
        row('CPU', first_line("lscpu | awk -F: '/^Model name/ { gsub(/^[ \\t]+/, \"\", $2); print $2; exit }'")),
        row('cores (nproc)', first_line('nproc')), row('built (UTC)', os.date('!%Y-%m-%d %H:%M')),
        '', ': Build environment, captured when this document was generated.' }
    return table.concat(out, '\n') .. '\n\n'
end

local BLOCK_PLACEHOLDERS = {
    ['summary-table'] = summary_table, environment = environment_table, ['results:'] = results_table,
    ['figure:'] = figure_line, ['tsv:'] = tsv_table, ['table:'] = result_table,
    ['claims:'] = claims_block, ['verdict:'] = verdict_block,
}
local BLOCK_KINDS = { 'summary-table', 'environment', 'results:', 'figure:', 'tsv:', 'table:', 'claims:', 'verdict:' }
-- kind and argument of a block placeholder (an HTML comment alone on its line), or nil
local function block_placeholder(comment)
    local body = trim(comment):match('^<!%-%-%s*(.-)%-%->$')
    if not body then return nil end
    for _, kind in ipairs(BLOCK_KINDS) do
        if body:sub(1, #kind) == kind then return kind, trim(body:sub(#kind + 1)) end
    end
end
-- the markdown of a block placeholder, or nil if COMMENT is none
local function expand_block(comment)
    local kind, arg = block_placeholder(comment)
    if kind then return BLOCK_PLACEHOLDERS[kind](trim(comment), arg) end
end

-- ---------------------------------------------------------------- inline placeholders (markdown out)

-- ID[@TIER] -> id, the tiers to search
local function id_and_tiers(spec)
    if spec:find('@', 1, true) then return before_last(spec, '@'), { after_last(spec, '@') } end
    return spec, TIERS
end
local function only_quick(tiers) return #tiers == 1 and tiers[1] == 'quick' end

-- a printf format of one number (%.3g, %.0f, %.2e ...)
local function number_format(f) return f:match('^%%[-+ 0#]*%d*[eEfgG]$') or f:match('^%%[-+ 0#]*%d*%.%d+[eEfgG]$') end

-- {{ID:Q}} or {{ID:Q:FMT}}: "value +- stderr" (%.4g, %.2g), or with FMT the value in that printf
-- format, followed by "+- stderr" only if the stderr is a positive number
local function inline_value(spec, arg)
    local ph = '{{' .. spec .. ':' .. arg .. '}}'
    local q, format = arg, nil
    if arg:find(':', 1, true) then q, format = before(arg, ':'), after(arg, ':') end
    if format and not number_format(format) then
        return missing(ph, 'expected PAPER/EXP:QUANTITY:FMT with FMT a printf number format (%.3g, %.0f ...)', 'missing: ' .. spec .. ':' .. arg)
    end
    local id, tiers = id_and_tiers(spec)
    for _, t in ipairs(tiers) do
        local v, se
        if valid_result(id, t) then v, se = summary_value(id, t, q) end
        if v then
            local text
            if format then
                text = string.format(format, awk_number(v))
                if is_number(se) and awk_number(se) > 0 then text = text .. string.format(' +- %.2g', awk_number(se)) end
            else
                text = string.format('%.4g +- %.2g', awk_number(v), awk_number(se))
            end
            return text .. (t ~= 'paper' and ' (' .. t .. ' tier)' or '')
        end
    end
    if only_quick(tiers) and awaits_quick(id) then return pending(id) end
    return missing(ph, 'no such quantity in results/' .. id .. '/{' .. table.concat(tiers, ',') .. '}/summary.tsv',
                   'missing: ' .. spec .. ':' .. q)
end

local function inline_verdict(id)
    local v = verdict_of(id)
    if v.tier == '-' then return missing('{{verdict:' .. id .. '}}', 'no results for ' .. id, 'missing verdict: ' .. id) end
    local s = '**' .. v.verdict .. '** (' .. v.tier .. ' tier'
    if v.verdict == '[Re]' then return s .. string.format(': %d of %d claims pass)', v.cp, v.cp) end
    if v.verdict == 'invalid' then return s .. string.format(': %d of %d gates pass)', v.gp, v.gt) end
    if v.cp + v.cf + v.cu == 0 then return s .. ')' end
    -- every other verdict names its claims
    local by, parts = claims_by_outcome(id, v.tier), {}
    if #by.PASS > 0 then parts[#parts + 1] = 'pass ' .. name_list(by.PASS, 6) end
    if #by.FAIL > 0 then parts[#parts + 1] = 'fail ' .. name_list(by.FAIL, 6) end
    if #by.UNRESOLVED > 0 then
        parts[#parts + 1] = 'unresolved ' .. name_list(by.UNRESOLVED, 6)
            .. ((v.decide ~= '-' and v.decide ~= 'inf') and string.format(' (a run ×%s as long would decide them)', v.decide) or '')
    end
    return s .. ': ' .. table.concat(parts, '; ') .. ')'
end

-- {{outcome:ID[@TIER]:Q}}: the decision-rule outcome of band row Q (a claim or gate of bands.tsv) at
-- the tier the experiment's verdict uses, or at TIER, as the claims tables show it (a coloured
-- word, XFAIL as FAIL with its title; UNRESOLVED with the factor that decides it), so that prose
-- saying whether a row passes follows the row when the result changes
local function inline_outcome(arg)
    local ph = '{{outcome:' .. arg .. '}}'
    local spec, q = before_last(arg, ':'), after_last(arg, ':')
    if not arg:find(':', 1, true) or spec == '' or q == '' then
        return missing(ph, 'expected outcome:PAPER/EXP[@TIER]:QUANTITY', 'missing outcome: ' .. arg)
    end
    local id, tier = spec, nil
    if spec:find('@', 1, true) then id, tier = before_last(spec, '@'), after_last(spec, '@')
    else tier = verdict_of(id).tier end
    if tier == '-' then return missing(ph, 'no results for ' .. id, 'missing outcome: ' .. arg) end
    for _, r in ipairs(band_rows(id, tier)) do
        if r[2] == q and (r[13] == 'claim' or r[13] == 'gate') then
            return row_outcome(r) .. (tier ~= 'paper' and ' (' .. tier .. ' tier)' or '')
        end
    end
    return missing(ph, 'no claim or gate row ' .. q .. ' of ' .. id .. ' at tier ' .. tier, 'missing outcome: ' .. arg)
end

-- the CPU seconds of one experiment ID[@TIER] as {{cpu:}} finds them: 'ok', seconds (string), tier |
-- 'quick', id (awaits the quick tier) | 'missing'
local function cpu_of(spec)
    local tier, cpu
    if spec:find('@', 1, true) then
        local id = before_last(spec, '@'); tier = after_last(spec, '@')
        if tier == 'quick' and awaits_quick(id) then return 'quick', id end
        cpu = valid_result(id, tier) and provenance(id, tier, 'cpu_seconds') or ''
        if not valid_result(id, tier) then tier = '-' end
    else
        local v = verdict_of(spec); tier, cpu = v.tier, v.cpu
    end
    if tier == '-' or cpu == '' or cpu == '-' then return 'missing' end
    return 'ok', cpu, tier
end

-- {{cpu:SPEC}} (CPU seconds) and {{cpu-h:SPEC}} (CPU-hours, 3 digits): SPEC one experiment
-- ID[@TIER], or several joined by '+' (their total, each from its provenance.tsv)
local function inline_cpu(spec, hours)
    local ph = '{{' .. (hours and 'cpu-h' or 'cpu') .. ':' .. spec .. '}}'
    local total, mark = 0, nil
    for _, one in ipairs(split(spec, '+')) do
        local status, cpu, tier = cpu_of(trim(one))
        if status == 'quick' then return pending(cpu) end
        if status ~= 'ok' then return missing(ph, 'no results or no cpu_seconds for ' .. one, 'missing CPU time: ' .. spec) end
        total = total + awk_number(cpu)
        if tier ~= 'paper' then mark = tier end
    end
    local text = hours and string.format('%.3g', total / 3600) or string.format('%.0f', total)
    return text .. (mark and ' (' .. mark .. ' tier)' or '')
end

-- ROW -> the columns it names and a test of a row: its first field is ROW, or, for
-- NAME=VALUE[&NAME=VALUE...], column NAME holds VALUE for every pair
local function row_test(row)
    if not row:find('=', 1, true) then return {}, function(f) return f[1] == row end end
    local keys, names = {}, {}
    for _, kv in ipairs(split(row, '&')) do
        keys[#keys + 1] = { before(kv, '='), after(kv, '=') or '' }; names[#names + 1] = keys[#keys][1]
    end
    return names, function(f, columns)
        for _, k in ipairs(keys) do if (f[columns[k[1]]] or '') ~= k[2] then return false end end
        return true
    end
end

-- one cell of a TSV file (COL, or VCOL+-SECOL for "value +- stderr"; numbers printed to 4 and 2
-- digits): the cell text, or nil and the reason
local function tsv_cell(lines, row, col)
    local header, columns, rows = tsv_rows(lines)
    if not header then return nil, 'empty file' end
    local vname, sename = col, nil
    if col:find('+-', 1, true) then vname, sename = before(col, '+-'), after(col, '+-') end
    local names, matches = row_test(row)
    names[#names + 1] = vname; names[#names + 1] = sename
    for _, n in ipairs(names) do if not columns[n] then return nil, 'no column ' .. n end end
    local function cell(f, name, p) return fmt_if_number(p, f[columns[name]] or '') end
    for _, f in ipairs(rows) do
        if matches(f, columns) then
            return cell(f, vname, '%.4g') .. (sename and ' +- ' .. cell(f, sename, '%.2g') or '')
        end
    end
    return nil, 'no row ' .. row
end

-- {{tsv:PATH:ROW:COL}}: returns 'ok', text, tier ('' if not a result's file) | 'quick', id | 'error', markdown
local function tsv_lookup(spec)
    local ph, shown = '{{tsv:' .. spec .. '}}', 'missing: tsv:' .. spec
    local parts = split(spec, ':')
    if #parts ~= 3 or parts[3] == '' then return 'error', missing(ph, 'expected tsv:PATH:ROW:COL', shown) end
    local p, row, col = parts[1], parts[2], parts[3]
    local id, tier = p:match('^results/([^/]*/[^/]*)/([^/]*)/.')
    if id then
        if not valid_result(id, tier) then
            if tier == 'quick' and awaits_quick(id) then return 'quick', id end
            return 'error', missing(ph, 'results/' .. id .. '/' .. tier .. ' is not a valid result (no summary.tsv or INCOMPLETE)', shown)
        end
    end
    local lines = read_lines(ROOT .. '/' .. p)
    if not lines then return 'error', missing(ph, 'no file ' .. p, shown) end
    local v, why = tsv_cell(lines, row, col)
    if not v then return 'error', missing(ph, p .. ': ' .. why, shown) end
    return 'ok', v, tier or ''
end

local function inline_tsv(spec)
    local status, v, tier = tsv_lookup(spec)
    if status == 'quick' then return pending(v) end
    if status == 'error' then return v end
    return v .. (tier ~= '' and tier ~= 'paper' and ' (' .. tier .. ' tier)' or '')
end

local function inline_bench(arg)
    local ph, shown = '{{bench:' .. arg .. '}}', 'missing: bench:' .. arg
    local parts = split(arg, ':')
    if #parts ~= 3 or parts[1] == '' or parts[1]:find('/', 1, true) or parts[3] == '' then
        return missing(ph, 'expected bench:FILE:ROW:COL (FILE in bench/)', shown)
    end
    local file, row, col = parts[1], parts[2], parts[3]
    local _, columns, rows = tsv_rows(read_lines(ROOT .. '/bench/' .. file) or {})
    local value, date_commit = '', ''
    for _, f in ipairs(rows) do
        if f[1] == 'date, commit' then date_commit = ' ' .. (f[2] or '') .. ', ' .. (f[3] or '') end
        if f[1] == row and columns[col] and (f[columns[col]] or '') ~= '' then value = f[columns[col]] end
    end
    if value == '' then return 'not measured (run `make bench`)' end
    return value .. ' (`make bench`' .. date_commit .. ')'
end

-- the markdown of inline placeholder {{KIND:ARG}}
local function expand_inline(kind, arg)
    if kind == 'verdict' then return inline_verdict(arg)
    elseif kind == 'outcome' then return inline_outcome(arg)
    elseif kind == 'cpu' then return inline_cpu(arg)
    elseif kind == 'cpu-h' then return inline_cpu(arg, true)
    elseif kind == 'tsv' then return inline_tsv(arg)
    elseif kind == 'calc' or kind == 'pct' or kind == 'ratio' or kind == 'diff' or kind == 'sigmas' then
        return missing('{{' .. kind .. ':' .. arg .. '}}', 'no expressions in the text: a number a section needs is a quantity its'
            .. " experiment's analysis writes, quoted as {{PAPER/EXP:QUANTITY[:FMT]}} (issue 40 item 7)", 'missing: ' .. kind .. ':' .. arg)
    elseif kind == 'bench' then return inline_bench(arg)
    else return inline_value(kind, arg) end
end

-- ---------------------------------------------------------------- the document tree

local INLINE_RE = '{{([^:}\n]+):([^}\n]+)}}'
local MARKDOWN_OUT = { wrap_text = 'wrap-preserve' }

-- the markdown of a placeholder as written back by pandoc's writer, back to its source text
local function unescape(s) return (s:gsub('\\(%p)', '%1')) end

-- a line of written markdown that is a raw HTML comment alone: the comment
local function raw_comment_line(l) return l:match('^`+(<!%-%-.-%-%->)`+{=html}$') end

-- every inline placeholder of markdown text MD replaced by its expansion; every line that is
-- a block placeholder (a raw HTML comment alone on its line) by its blocks
local function expand_markdown(md)
    local lines = split(md, '\n')
    for i, l in ipairs(lines) do
        local comment = raw_comment_line(l)
        local block = comment and expand_block(comment)
        if block then lines[i] = block:gsub('\n$', '')     -- the line's own end is the join's
        else
            local out, pos = {}, 1
            while true do
                local s, e, kind, arg = l:find(INLINE_RE, pos)
                if not s then out[#out + 1] = l:sub(pos); break end
                out[#out + 1] = l:sub(pos, s - 1)
                out[#out + 1] = expand_inline(unescape(kind), unescape(arg))
                pos = e + 1
            end
            lines[i] = table.concat(out)
        end
    end
    return table.concat(lines, '\n')
end

local function holds_placeholder(md)
    if md:find(INLINE_RE) then return true end
    for _, l in ipairs(split(md, '\n')) do
        local comment = raw_comment_line(l)
        if comment and block_placeholder(comment) then return true end
    end
    return false
end

-- read with the options of the document's own reading (its columns decide a pipe table's widths)
local function read_markdown(md) return pandoc.read(md, 'markdown', PANDOC_READER_OPTIONS).blocks end

-- The markdown reader may pair a '*' or '^' inside a placeholder with one in another placeholder or
-- in the text ("[a]^2*1500}} in torque^2 ... ([b]/0.005)^2}}" holds a superscript); such a container,
-- which straddles a placeholder's braces, is put back as its delimiters around its content.
local DELIMITERS = { Emph = '*', Strong = '**', Superscript = '^', Subscript = '~', Strikeout = '~~' }
local function straddles_braces(el)
    local text = pandoc.utils.stringify(el):gsub('{{[^{}]-}}', '')
    return text:find('{{', 1, true) or text:find('}}', 1, true)
end
local function unpair_delimiters(inlines)
    local out = pandoc.List()
    for _, el in ipairs(inlines) do
        local d = DELIMITERS[el.t]
        if d and straddles_braces(el) then
            out:insert(pandoc.Str(d)); out:extend(unpair_delimiters(el.content)); out:insert(pandoc.Str(d))
        else
            if d then el.content = unpair_delimiters(el.content) end
            out:insert(el)
        end
    end
    return out
end

-- a paragraph (or plain block) holding placeholders: written back to markdown, filled, read again
local function fill_inlines(block)
    local raw = false
    for _, el in ipairs(block.content) do if el.t == 'RawInline' and el.format == 'html' then raw = true end end
    if not raw and not pandoc.utils.stringify(block):find('{{', 1, true) then return nil end
    block.content = unpair_delimiters(block.content)
    local md = pandoc.write(pandoc.Pandoc({ block }), 'markdown', MARKDOWN_OUT)
    if not holds_placeholder(md) then return nil end
    local blocks = read_markdown(expand_markdown(md))
    if block.t == 'Plain' and #blocks == 1 and blocks[1].t == 'Para' then return pandoc.Plain(blocks[1].content) end
    return blocks
end

-- a raw HTML comment block that is a block placeholder: its blocks
local function fill_raw_block(block)
    if block.format ~= 'html' then return nil end
    local md = expand_block(block.text)
    if md == nil then return nil end
    return read_markdown(md)
end

-- one notice per section (the blocks from a heading to the next heading) that holds a quick-tier
-- mark, right after its heading (before the first heading: at the top)
local function holds_quick_mark(block)
    local found = false
    pandoc.walk_block(pandoc.Div({ block }), { Span = function(sp)
        if sp.classes:includes(QUICK_CLASS) then found = true end
    end })
    return found
end
local function quick_notices(doc)
    if npend == 0 then return nil end
    local out, start, marked = pandoc.List(), 1, false
    local function close_section()
        if marked then
            out:insert(start, pandoc.Div(read_markdown(QUICK_NOTICE), pandoc.Attr('', { 'quick-notice' })))
        end
        marked = false
    end
    for _, b in ipairs(doc.blocks) do
        if b.t == 'Header' then close_section(); out:insert(b); start = #out + 1
        else
            out:insert(b)
            marked = marked or holds_quick_mark(b)
        end
    end
    close_section()
    doc.blocks = out
    return doc
end

-- HTML: every table in a box of its own that scrolls sideways (paper.css .table-wrap), so that a
-- table wider than a phone's screen does not widen the page (tests/browser.py)
local function wrap_table(t)
    if FORMAT:match('html') then return pandoc.Div({ t }, pandoc.Attr('', { 'table-wrap' })) end
end

-- at the end: a placeholder the walk did not reach (a heading, metadata) is an error, not left as is
local function report_leftovers(doc)
    local text = pandoc.write(doc, 'markdown', MARKDOWN_OUT) .. '\n' .. pandoc.utils.stringify(doc.meta)
    for kind, arg in text:gmatch(INLINE_RE) do
        problem('{{' .. unescape(kind) .. ':' .. unescape(arg) .. '}}', 'placeholder in a place the filter does not fill (a heading, the metadata)')
    end
end

local function finish(doc)
    report_leftovers(doc)
    if npend > 0 then
        local n = 0; for _ in pairs(pending_ids) do n = n + 1 end
        io.stderr:write(string.format('%s: %d placeholder(s) await the quick tier of %d experiment(s), which is not committed: '
            .. 'marked — with a notice in their sections; `make figures` computes it\n', NAME, npend, n))
    end
    if nerr > 0 then
        io.stderr:write(string.format('%s: %d placeholder(s) could not be filled; no output written\n', NAME, nerr))
        os.exit(1)
    end
    return doc
end

-- a heading "PAPER/EXP: ..." of an experiment: the anchor the summary links to (first, so that the
-- summary knows which experiments have a section)
local function anchor_heading(h)
    local id = pandoc.utils.stringify(h):match('^([%w%-%.]+/[%w%-%.]+):')
    if id and exists(ROOT .. '/experiments/' .. id) then
        h.identifier = anchor_of(id); sections[id] = true
        return h
    end
end

return {
    { Header = anchor_heading },
    { RawBlock = fill_raw_block, Para = fill_inlines, Plain = fill_inlines },
    { Pandoc = quick_notices },
    { Table = wrap_table },
    { Pandoc = finish },
}
