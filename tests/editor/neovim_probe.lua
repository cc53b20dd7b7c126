-- Run by tests/editor/test_neovim.py after the README's lines and the file opened: waits for
-- the buffer's diagnostics (polled every 100 ms, at most 600 times), writes them with the names
-- of the language servers attached to the buffer as JSON to $RDISC_PROBE_OUT, and quits.
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
local out = assert(io.open(os.getenv("RDISC_PROBE_OUT"), "w"))
out:write(vim.json.encode({ arrived = arrived, filetype = vim.bo.filetype, clients = clients,
                            diagnostics = diagnostics }))
out:close()
vim.cmd("qall!")
