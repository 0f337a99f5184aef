'use strict';
document.querySelectorAll('table.sortable').forEach(function (table) {
  var heads = table.tHead.rows[0].cells;
  function sort(column, up) {
    Array.prototype.forEach.call(heads, function (h) { h.classList.remove('sorted-up', 'sorted-down'); });
    heads[column].classList.add(up ? 'sorted-up' : 'sorted-down');
    var body = table.tBodies[0];
    var rows = Array.prototype.slice.call(body.rows);
    function key(row) {
      var cell = row.cells[column];
      var v = cell.getAttribute('data-sort');
      return v === null ? cell.textContent.trim() : parseFloat(v);
    }
    rows.sort(function (a, b) {
      var ka = key(a), kb = key(b);
      var c = typeof ka === 'number' ? ka - kb : ka.localeCompare(kb, undefined, { numeric: true, sensitivity: 'base' });
      return up ? c : -c;
    });
    rows.forEach(function (row) { body.appendChild(row); });
  }
  Array.prototype.forEach.call(heads, function (th, column) {
    th.classList.add('sortable');
    th.tabIndex = 0;
    th.title = 'sort by this column';
    function click() {
      var up = !th.classList.contains('sorted-up');
      sort(column, up);
      history.replaceState(null, '', '#sort=' + column + (up ? '' : '-down'));
    }
    th.addEventListener('click', click);
    th.addEventListener('keydown', function (e) { if (e.key === 'Enter') click(); });
  });
  var asked = /^#sort=(\d+)(-down)?$/.exec(location.hash);
  if (asked && +asked[1] < heads.length) sort(+asked[1], !asked[2]);
});
document.querySelectorAll('.compare').forEach(function (section) {
  var range = section.querySelector('input');
  var top = section.querySelector('.top');
  function show() { top.style.clipPath = 'inset(0 0 0 ' + range.value + '%)'; }
  range.addEventListener('input', show);
  document.addEventListener('keydown', function (e) {
    if (e.key === 't') { range.value = range.value > 50 ? 0 : 100; show(); }
  });
  section.hidden = false;
  show();
});
