-- The Neovim set-up of docs/editors/neovim.png (see docs/editors.md, "The screenshot").
vim.o.termguicolors = false
vim.o.number = true
vim.o.laststatus = 2
vim.cmd("syntax off")
vim.api.nvim_create_autocmd("BufRead", { pattern = "*.nc", callback = function()
  local id = vim.lsp.start_client({ name = "gcnc", cmd = {"java", "-jar", os.getenv("GCNC_JAR") or "build/libs/gcnc.jar", "lsp"},
    root_dir = vim.fn.getcwd(), init_options = {simulateAfterMs = -1, explainFolder = vim.fn.tempname()} })
  vim.lsp.buf_attach_client(0, id)
end })
vim.diagnostic.config({ virtual_text = { prefix = "●" }, severity_sort = true })
vim.cmd("highlight NormalFloat ctermbg=236 ctermfg=252")
vim.cmd("highlight SignColumn ctermbg=NONE")
