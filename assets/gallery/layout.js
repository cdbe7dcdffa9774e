// Packs the cards of each grid without holes: every card spans as many
// thin rows as its height needs, and the grid fills each gap with the next
// card that fits (grid-auto-flow: dense). Without scripts the page is a
// plain grid.
(() => {
  const ROW = 4;
  const pack = () => {
    for (const grid of document.querySelectorAll('.grid')) {
      grid.classList.add('packed');
      const gap = parseFloat(getComputedStyle(grid).columnGap) || 0;
      for (const card of grid.children) {
        const h = card.getBoundingClientRect().height;
        card.style.gridRowEnd = 'span ' + Math.ceil((h + gap) / ROW);
      }
    }
  };
  let queued = false;
  const later = () => {
    if (!queued) {
      queued = true;
      requestAnimationFrame(() => { queued = false; pack(); });
    }
  };
  document.addEventListener('DOMContentLoaded', pack);
  window.addEventListener('load', pack);
  window.addEventListener('resize', later);
  document.addEventListener('load', later, true);
  document.addEventListener('loadedmetadata', later, true);
})();
