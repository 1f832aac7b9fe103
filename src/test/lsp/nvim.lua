-- Neovim's own LSP client against gcnc lsp (LspClientTest): headless, no user config (nvim --headless -u NONE
-- -c 'luafile nvim.lua'); Debian 12's Neovim 0.7 has vim.lsp.start_client (vim.lsp.start is 0.8+).
-- Opens a program, waits for the diagnostics and compares them with gcnc check --format json, then asks
-- for a hover and a definition. Prints "nvim: ok" and quits 0, or prints what differed and quits 1.
local jar = os.getenv("GCNC_JAR")
local dir = vim.fn.tempname()
vim.fn.mkdir(dir, "p")
local function write(name, text)
  local f = assert(io.open(dir .. "/" .. name, "w"))
  f:write(text)
  f:close()
end
write(".gcnc", "machine = haas\n")
write("O1000.nc", "O1000\nG00 X40. Z1.\nM99\n")
write("part.nc", table.concat({"O0001", "G21 G40 G99", "TO303", "G50 S2000", "G97 S500 M03",
  "G00 X50 Z2.", "M98 P1000", "G01 X40. Z-10 F0.2", "M30", ""}, "\n"))

local function fail(what)
  io.stdout:write("nvim: FAILED: " .. what .. "\n")
  vim.cmd("cquit 1")
end

local function main()
  vim.cmd("edit " .. dir .. "/part.nc")
  local buf = vim.api.nvim_get_current_buf()
  local id = vim.lsp.start_client({
    name = "gcnc",
    cmd = {"java", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-jar", jar, "lsp"},
    root_dir = dir,
    init_options = {simulateAfterMs = -1, explainFolder = dir .. "/.explain"},
  })
  if not id then fail("the client did not start") end
  vim.lsp.buf_attach_client(buf, id)
  if not vim.wait(30000, function() return #vim.diagnostic.get(buf) > 0 end, 20) then
    fail("no diagnostics")
  end

  -- the JSON on standard output only (system() would mix in the summary on standard error)
  local want = vim.fn.json_decode(vim.fn.system("java -XX:TieredStopAtLevel=1 -jar " .. vim.fn.shellescape(jar)
    .. " check --machine haas --format json " .. vim.fn.shellescape(dir .. "/part.nc") .. " 2>/dev/null")).diagnostics
  local got = {}
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    local code = d.code or (d.user_data and d.user_data.lsp and d.user_data.lsp.code)
    table.insert(got, string.format("%s@%d:%d", code, d.lnum + 1, d.col + 1))
  end
  table.sort(got)
  local expected = {}
  for _, d in ipairs(want) do table.insert(expected, string.format("%s@%d:%d", d.code, d.line, d.column)) end
  table.sort(expected)
  if table.concat(got, " ") ~= table.concat(expected, " ") then
    fail("diagnostics " .. table.concat(got, " ") .. " ~= gcnc check " .. table.concat(expected, " "))
  end

  local doc = {uri = vim.uri_from_bufnr(buf)}
  local hover = vim.lsp.buf_request_sync(buf, "textDocument/hover", {textDocument = doc, position = {line = 4, character = 1}}, 10000)
  local text = hover and hover[id] and hover[id].result and hover[id].result.contents.value or ""
  if not text:find("**G97**", 1, true) or not text:find("500. rpm", 1, true) then fail("hover: " .. text) end

  local def = vim.lsp.buf_request_sync(buf, "textDocument/definition", {textDocument = doc, position = {line = 6, character = 5}}, 10000)
  local loc = def and def[id] and def[id].result and def[id].result[1]
  if not loc or loc.uri ~= vim.uri_from_fname(dir .. "/O1000.nc") then fail("definition: " .. vim.inspect(def)) end

  io.stdout:write("nvim: ok (" .. #got .. " diagnostics as gcnc check's, hover, definition)\n")
  vim.lsp.stop_client(id)
  vim.wait(5000, function() return vim.lsp.get_client_by_id(id) == nil end, 20)
  vim.cmd("qall!")
end

local ok, err = pcall(main)
if not ok then fail(tostring(err)) end
