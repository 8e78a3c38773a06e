"""The report's pages, in order: what the manifest holds decides which exist."""
import closed_form_page
import contact_page
import front_page
import gate_pages
import glossary_page
import family_page
import drape_pages
import energy_pages
import missing_page
import page_commands
import performance_page
import physical_trade_page
import refine_pages
import series_pages
import stability_pages
import timings_page
import trade_pages
import verdict_page


def pages(ctx):
    m = ctx.manifest
    result = [front_page.page(ctx)] + gate_pages.pages(ctx)
    if m.get("headlines", {}).get("verdicts"):
        result.insert(1, verdict_page.page(ctx))
    if any(c["group"] == "suite" for c in m["comparisons"]):
        result.insert(2, closed_form_page.page(ctx))
    result += contact_page.pages(m)
    result += family_page.pages(m)
    result += trade_pages.pages(m)
    result += stability_pages.pages(m)
    result += energy_pages.pages(m)
    result += drape_pages.pages(m)
    result += refine_pages.pages(m)
    result += physical_trade_page.pages(m)
    result += series_pages.pages(m)
    if m.get("bench"):
        result.append(performance_page.page(m["bench"]))
    result.append(glossary_page.page())
    if m["missing"]:
        result.append(missing_page.page(m["missing"]))
    if m.get("timings"):
        result.append(timings_page.page(m["timings"]))
    return page_commands.attach(result, m)
