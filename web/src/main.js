// Draws what the data holds: a run (everything), an eval (trajectories and
// errors) or a bench (tables with bars). LV.ready settles when all is drawn.
async function drawReport() {
  // three.js compiles while the plots are drawn.
  const three = DATA.kind === 'run' ? loadThree() : null;
  document.title = DATA.title;
  document.getElementById('app').append(el('h1', { text: DATA.title }));
  if (DATA.kind === 'bench') { benchSections(); return; }
  if (DATA.stats) summarySection();
  trajectorySection();
  errorSection();
  if (DATA.stats) { detectionSection(); fusionSection(); loopSection(); timingSection(); }
  if (three) await view3dSection(three);
}
LV.ready = drawReport();
LV.ready.catch((error) => {
  document.getElementById('app').append(el('p', { class: 'error', text: 'The report could not be drawn: ' + error }));
  console.error(error);
});
