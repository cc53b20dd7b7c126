-- Run by tests/editor/test_neovim.py after the README's lines and the file opened, as a user
-- would press the keys of Neovim's LSP client: waits for the buffer's diagnostics (polled every
-- 100 ms, at most 600 times), applies the quick fix of the first, waits for them to clear, asks
-- for a hover, a definition and completions, renames the primitive, reads the semantic token at $RDISC_PROBE_AT's
-- positions, formats the buffer, then writes what it saw as JSON to $RDISC_PROBE_OUT and quits.
local at = vim.json.decode(os.getenv("RDISC_PROBE_AT"))
local uri = vim.uri_from_bufnr(0)
local arrived = vim.wait(60000, function() return #vim.diagnostic.get(0) > 0 end, 100)
local diagnostics = {}
for _, d in ipairs(vim.diagnostic.get(0)) do
  table.insert(diagnostics, { lnum = d.lnum, col = d.col, end_lnum = d.end_lnum, end_col = d.end_col,
                              code = d.code, message = d.message, source = d.source, severity = d.severity })
end
local clients = {}
for _, client in ipairs(vim.lsp.get_clients({ bufnr = 0 })) do
  table.insert(clients, client.name)
end

local function ask(method, params)
  local answers = vim.lsp.buf_request_sync(0, method, params, 30000) or {}
  for _, answer in pairs(answers) do
    if answer.result ~= nil then return answer.result end
  end
  return vim.NIL
end

local function at_position(name)
  return { textDocument = { uri = uri }, position = { line = at[name][1], character = at[name][2] } }
end

-- The quick fix of the first diagnostic, applied as Neovim's code action menu applies it.
local fixes = {}
local cleared = false
local first = vim.diagnostic.get(0)[1]
if first ~= nil then
  local lsp = first.user_data.lsp
  local actions = ask("textDocument/codeAction", { textDocument = { uri = uri }, range = lsp.range,
                                                   context = { diagnostics = { lsp } } })
  for _, action in ipairs(actions ~= vim.NIL and actions or {}) do
    table.insert(fixes, action.title)
  end
  if #fixes > 0 and actions[1].edit ~= nil then
    vim.lsp.util.apply_workspace_edit(actions[1].edit, "utf-16")
    cleared = vim.wait(60000, function() return #vim.diagnostic.get(0) == 0 end, 100)
  end
end

local hover = ask("textDocument/hover", at_position("hover"))
local definition = ask("textDocument/definition", at_position("definition"))
if definition ~= vim.NIL and definition.uri == nil then definition = definition[1] end

-- Completion where the call's name is typed: the names the place takes.
local completion = ask("textDocument/completion", at_position("completion"))
local offered = {}
for _, item in ipairs(completion ~= vim.NIL and (completion.items or completion) or {}) do
  offered[item.label] = true
end

-- Rename the call's primitive, as `vim.lsp.buf.rename` does from the cursor; every use follows.
vim.api.nvim_win_set_cursor(0, { at.rename[1] + 1, at.rename[2] })
vim.lsp.buf.rename(at.rename[3])
local renamed = vim.wait(60000, function()
  return table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), "\n"):find(at.rename[3], 1, true) ~= nil
end, 100)

local function token_at(name)
  local tokens = vim.lsp.semantic_tokens.get_at_pos(0, at[name][1], at[name][2]) or {}
  return tokens[1] and tokens[1].type or nil
end
vim.wait(60000, function() return token_at("token") ~= nil end, 100)
local token = token_at("token")

vim.lsp.buf.format({ async = false, timeout_ms = 30000 })
local formatted = table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), "\n") .. "\n"

local out = assert(io.open(os.getenv("RDISC_PROBE_OUT"), "w"))
out:write(vim.json.encode({
  arrived = arrived, filetype = vim.bo.filetype, clients = clients, diagnostics = diagnostics,
  fixes = fixes, cleared = cleared, renamed = renamed,
  completed = offered[at.completion[3]] == true,
  hover = hover ~= vim.NIL and hover.contents.value or vim.NIL,
  definition = definition ~= vim.NIL and { uri = definition.uri, line = definition.range.start.line } or vim.NIL,
  token = token, formatted = formatted,
}))
out:close()
vim.cmd("qall!")
